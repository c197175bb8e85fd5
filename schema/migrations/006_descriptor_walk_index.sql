-- 006_descriptor_walk_index: the descriptor index's rows of one descriptor and width class in
-- object id order. The linguistic search's level scan walks a flat piece (a set's core, where
-- every row scores the same and ties go by id) in id order; without this index the walk went
-- through the primary key, reading each object's every descriptor row (a part has 11) to find
-- the one it wanted. With it a walk reads one entry per object of the class: at 1M parts a walk
-- of 20000 ids took 1.5 ms instead of 35 ms (docs/performance.md). The columns after object_id
-- make it covering, so a walk never visits the table.
CREATE INDEX IF NOT EXISTS descriptor_index_walk
  ON descriptor_index (kind, descriptor, width_class, object_id, support_lo, support_hi);
