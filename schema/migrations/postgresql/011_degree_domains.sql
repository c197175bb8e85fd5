-- 011_degree_domains for PostgreSQL: as schema/migrations/011_degree_domains.sql, every part and
-- shape is marked pending so the server recomputes its rows with degrees clamped into their
-- descriptors' domains.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape')
  ON CONFLICT (object_id) DO UPDATE SET generation = excluded.generation;
