-- 010_proportion_descriptors: the two proportions, flatness and slenderness (how much thinner and
-- how much longer a part is than it is wide; query/linguistic/descriptors.h), join the descriptor
-- index. As 008 did, every part and shape is marked pending so the server recomputes its rows (all
-- descriptors) at startup; until then the prefilter returns pending objects as candidates and
-- scoring describes their documents, so no answer misses them.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT OR REPLACE INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape');
