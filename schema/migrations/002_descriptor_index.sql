-- 002_descriptor_index: the linguistic descriptor index (docs/api.md §5; Zhang, Pham & Chen, §5).
-- For each live part and shape, the fuzzy value of every descriptor (query/linguistic/descriptors.h:
-- squariness, roundness, ..., elongation) of every component, so POST /query/linguistic can
-- prefilter candidates in SQL by support overlap (the derivation principle of SQLf: a fuzzy
-- condition can only be satisfied to a degree > 0 where the value's support meets the condition's
-- support) and score only those exactly. Latest version only: replaced on every write, deleted
-- with the object. The server computes the rows (describePart); the store only keeps them.
--
-- component: which leaf of a shape (pre-order over the resolved tree, references expanded); a
-- part has one component, 0.

-- One row per (object, component, descriptor): the value's support [support_lo, support_hi] and
-- core [core_lo, core_hi].
--
-- The overlap of [support_lo, support_hi] with a condition's [a, b] is support_lo <= b AND
-- support_hi >= a: two open-ended ranges, which no B-tree serves on its own (an index on
-- support_lo scans every row with support_lo <= b). width_class bounds the width
-- w = support_hi - support_lo <= 2^width_class (crisp values: class -1100, w = 0), so inside one
-- class support_lo >= a - 2^width_class as well: the prefilter runs one range scan
-- support_lo BETWEEN a - 2^class AND b per class present (descriptor_classes), each on the
-- covering index below, and checks support_hi >= a inside the index.
-- kind is the object's (never changes), so a search for parts never reads the rows of shapes.
CREATE TABLE descriptor_index (
  object_id INTEGER NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  kind TEXT NOT NULL,
  component INTEGER NOT NULL,
  descriptor TEXT NOT NULL,
  width_class INTEGER NOT NULL,
  support_lo REAL NOT NULL,
  core_lo REAL NOT NULL,
  core_hi REAL NOT NULL,
  support_hi REAL NOT NULL,
  PRIMARY KEY (object_id, component, descriptor)
) WITHOUT ROWID;
CREATE INDEX descriptor_index_overlap
  ON descriptor_index (kind, descriptor, width_class, support_lo, support_hi);

-- The width classes each descriptor has rows in (only ever added: a class without rows left
-- costs one empty index seek).
CREATE TABLE descriptor_classes (
  descriptor TEXT NOT NULL,
  width_class INTEGER NOT NULL,
  PRIMARY KEY (descriptor, width_class)
) WITHOUT ROWID;

-- The exact descriptor values of each component, encoded by the server (server/service/descriptor_rows.h),
-- so scoring a candidate part reads one row instead of parsing and describing its document.
CREATE TABLE descriptor_values (
  object_id INTEGER NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  component INTEGER NOT NULL,
  descriptor_values BLOB NOT NULL,
  PRIMARY KEY (object_id, component)
);

-- Objects whose rows are missing or may be stale: every object that existed before this
-- migration (backfilled by the server at startup, which logs it), every object reaching an
-- object that got a new version (its components changed under it), and every object written
-- with references (its rows were computed from documents read before the write transaction).
-- The prefilter always returns pending objects as candidates, so a stale row never hides a
-- match; the server recomputes them and clears the mark only if the generation it read is still
-- the latest (a write in between marks the object again with a higher generation).
CREATE TABLE descriptor_pending (
  object_id INTEGER PRIMARY KEY REFERENCES objects (id) ON DELETE CASCADE,
  generation INTEGER NOT NULL
);
-- The source of generations: one row, incremented by every marking.
CREATE TABLE descriptor_clock (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  generation INTEGER NOT NULL
);
INSERT INTO descriptor_clock (id, generation) VALUES (1, 1);

INSERT INTO descriptor_pending (object_id, generation)
  SELECT id, 1 FROM objects WHERE kind IN ('part', 'shape');
