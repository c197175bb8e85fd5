-- 006_descriptor_walk_index for PostgreSQL: the index of schema/migrations/006_descriptor_walk_index.sql,
-- the descriptor rows of one descriptor and width class in object id order, covering what a
-- walk of the linguistic search's level scan reads.
CREATE INDEX IF NOT EXISTS descriptor_index_walk
  ON descriptor_index (kind, descriptor, width_class, object_id, support_lo, support_hi);
