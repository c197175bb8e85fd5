-- 001_init: the store of db/store.h. Later migrations (002_..., compiled in the same way) add
-- room for the descriptor index and curves; this one holds objects, their
-- versions, the reference graph, normalised columns for prefilters and the evaluation cache.

-- One row per live object. AUTOINCREMENT so an id is never reused, even after a delete: a
-- client holding id 7 must never silently read a different object. Ids are shared by all kinds.
-- latest_version is denormalised from versions so "get the latest" is one primary-key lookup.
-- Times live on the versions (created_at of version 1 and of the latest one).
CREATE TABLE objects (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  kind TEXT NOT NULL CHECK (kind IN ('part', 'shape', 'curve', 'surface')),
  name TEXT NOT NULL,
  latest_version INTEGER NOT NULL
);
-- A name is unique among the live objects of its kind (deleting frees it).
CREATE UNIQUE INDEX objects_kind_name ON objects (kind, name);

-- Every version of every object, as given: PUT adds a row, old versions stay readable.
-- content_hash (db/content_hash.h) makes upserts idempotent and keys the evaluation cache.
CREATE TABLE versions (
  object_id INTEGER NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  version INTEGER NOT NULL,
  document TEXT NOT NULL,
  content_hash TEXT NOT NULL,
  created_at TEXT NOT NULL,  -- ISO 8601 UTC with milliseconds
  PRIMARY KEY (object_id, version)
) WITHOUT ROWID;

-- The reference graph: parent -> child for each object's LATEST version only (replaced on
-- every write), so a part used by a thousand trees is stored once and "who uses X" (delete
-- checks, cache invalidation) is an index lookup. child_id has no ON DELETE: deleting a child
-- that a live object still uses must fail (in_use) unless the parents go in the same statement.
CREATE TABLE refs (
  parent_id INTEGER NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  child_id INTEGER NOT NULL REFERENCES objects (id),
  PRIMARY KEY (parent_id, child_id)
) WITHOUT ROWID;
CREATE INDEX refs_child ON refs (child_id);

-- A part's fuzzy parameters per version, normalised to their support [lo, hi] and core [lo, hi]
-- (alpha-cuts at 0 and 1), so SQL can prefilter parts by parameter ranges before the exact
-- fuzzy comparison.
CREATE TABLE part_parameters (
  object_id INTEGER NOT NULL,
  version INTEGER NOT NULL,
  name TEXT NOT NULL,
  support_lo REAL NOT NULL,
  core_lo REAL NOT NULL,
  core_hi REAL NOT NULL,
  support_hi REAL NOT NULL,
  PRIMARY KEY (object_id, version, name),
  FOREIGN KEY (object_id, version) REFERENCES versions (object_id, version) ON DELETE CASCADE
) WITHOUT ROWID;
CREATE INDEX part_parameters_range ON part_parameters (name, support_lo, support_hi);

-- A shape's CSG tree per version, one row per node in pre-order, for structural search
-- ("shapes that subtract a cylinder from a box"). ref_id is the object a "ref" leaf resolved to
-- when the version was written; no foreign key, because an old version may name an object
-- deleted since (only the latest version's edges, in refs, keep their children alive).
CREATE TABLE csg_nodes (
  object_id INTEGER NOT NULL,
  version INTEGER NOT NULL,
  node INTEGER NOT NULL,
  parent INTEGER NOT NULL,       -- -1 for the root
  position INTEGER NOT NULL,     -- child position under the parent (difference is ordered)
  kind TEXT NOT NULL,            -- union, intersection, difference, part, ref
  operator TEXT,                 -- the node's operator document; NULL for zadeh and leaves
  ref_id INTEGER,
  transform TEXT,                -- the leaf's transform document; NULL when none
  PRIMARY KEY (object_id, version, node),
  FOREIGN KEY (object_id, version) REFERENCES versions (object_id, version) ON DELETE CASCADE
) WITHOUT ROWID;

-- Results of evaluating shapes, keyed by the caller (hash of the resolved document, resolution,
-- alphas, method). Any write to an object deletes the rows of that object and of everything that
-- reaches it, so a hit is never stale; vdb holds an optional OpenVDB grid.
CREATE TABLE eval_cache (
  key TEXT PRIMARY KEY,
  object_id INTEGER NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  result TEXT NOT NULL,
  vdb BLOB
);
CREATE INDEX eval_cache_object ON eval_cache (object_id);
