-- 005_drop_part_parameters: part_parameters held, per version of every part, the support and core
-- of each of its 14 fuzzy parameters, meant for SQL prefilters. No query ever read it: the
-- linguistic search prefilters on the descriptor index (002), the structural search on csg_nodes.
-- It was half the rows a part's write inserted (14 rows and 14 index entries of some 30), and
-- dropping it made a bulk import of parts 1.6x faster (docs/performance.md).
DROP INDEX IF EXISTS part_parameters_range;
DROP TABLE IF EXISTS part_parameters;
