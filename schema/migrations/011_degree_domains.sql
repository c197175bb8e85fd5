-- 011_degree_domains: every degree is read clamped into its descriptor's domain (descriptors.h,
-- "Degree domains": within 0.01 of an end no part reaches, such as squariness 1 or size 1). Every
-- part and shape is marked pending, as 010 did, so the server recomputes its rows at startup;
-- until then the prefilter returns pending objects as candidates and scoring describes their
-- documents, so no answer misses them.
UPDATE descriptor_clock SET generation = generation + 1;
INSERT OR REPLACE INTO descriptor_pending (object_id, generation)
  SELECT id, (SELECT generation FROM descriptor_clock) FROM objects WHERE kind IN ('part', 'shape');
