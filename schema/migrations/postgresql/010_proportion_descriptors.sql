-- 010_proportion_descriptors for PostgreSQL: as schema/migrations/010_proportion_descriptors.sql,
-- every part and shape is marked pending so the server recomputes its rows with flatness and
-- slenderness.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape')
  ON CONFLICT (object_id) DO UPDATE SET generation = excluded.generation;
