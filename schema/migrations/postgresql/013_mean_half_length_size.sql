-- 013_mean_half_length_size for PostgreSQL: as schema/migrations/013_mean_half_length_size.sql,
-- every part and shape is marked pending so the server recomputes its rows with the new size.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape')
  ON CONFLICT (object_id) DO UPDATE SET generation = excluded.generation;
