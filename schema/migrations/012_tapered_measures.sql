-- 012_tapered_measures: the measures (length, width, thickness) read the tapered solid's widest
-- section (query/linguistic/descriptors.h: a sharp cone's width is its base's diameter, where it
-- was the untapered A's). Every part and shape is marked pending, as 010 and 011 did, so the server
-- recomputes its rows at startup; until then the prefilter returns pending objects as candidates
-- and scoring describes their documents, so no answer misses them.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT OR REPLACE INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape');
