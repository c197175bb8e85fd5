-- 013_mean_half_length_size: size reads the arithmetic mean of the half-lengths (query/linguistic/
-- descriptors.h), where it read their geometric mean: a plate 6 across and 0.1 thick was smaller
-- than a stub 2 across. Every part and shape is marked pending, as 010 to 012 did, so the server
-- recomputes its rows at startup; until then the prefilter returns pending objects as candidates
-- and scoring describes their documents, so no answer misses them.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT OR REPLACE INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape');
