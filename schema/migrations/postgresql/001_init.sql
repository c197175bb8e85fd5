-- 001_init for PostgreSQL: the tables of schema/migrations/001_init.sql (read the reasons there),
-- in PostgreSQL's types. What differs:
-- - ids are BIGINT GENERATED ALWAYS AS IDENTITY: never reused (a sequence does not go back, not even
--   when a transaction rolls back), as SQLite's AUTOINCREMENT.
-- - text columns are COLLATE "C": names compare and sort bytewise, as in SQLite, whatever the
--   database's locale (a name unique in one backend is unique in the other; lists sort alike).
-- - refs.child_id's foreign key is checked at commit (below).
-- - numbers are DOUBLE PRECISION (SQLite's REAL), blobs BYTEA; no WITHOUT ROWID (PostgreSQL tables
--   are heaps with separate indexes).
CREATE TABLE objects (
  id BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  kind TEXT COLLATE "C" NOT NULL CHECK (kind IN ('part', 'shape', 'curve', 'surface')),
  name TEXT COLLATE "C" NOT NULL,
  latest_version INTEGER NOT NULL
);
CREATE UNIQUE INDEX objects_kind_name ON objects (kind, name);

CREATE TABLE versions (
  object_id BIGINT NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  version INTEGER NOT NULL,
  document TEXT NOT NULL,
  content_hash TEXT COLLATE "C" NOT NULL,
  created_at TEXT COLLATE "C" NOT NULL,
  PRIMARY KEY (object_id, version)
);

-- child_id's check is DEFERRABLE INITIALLY DEFERRED: a cascading delete removes parents and
-- children in one statement, and PostgreSQL runs the child_id check before the parent_id cascade
-- has removed the edges (SQLite checks both at the statement's end). The store refuses the delete
-- of a used object itself (in_use) before it deletes anything; this check stays as the backstop.
CREATE TABLE refs (
  parent_id BIGINT NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  child_id BIGINT NOT NULL REFERENCES objects (id) DEFERRABLE INITIALLY DEFERRED,
  PRIMARY KEY (parent_id, child_id)
);
CREATE INDEX refs_child ON refs (child_id);

CREATE TABLE part_parameters (
  object_id BIGINT NOT NULL,
  version INTEGER NOT NULL,
  name TEXT COLLATE "C" NOT NULL,
  support_lo DOUBLE PRECISION NOT NULL,
  core_lo DOUBLE PRECISION NOT NULL,
  core_hi DOUBLE PRECISION NOT NULL,
  support_hi DOUBLE PRECISION NOT NULL,
  PRIMARY KEY (object_id, version, name),
  FOREIGN KEY (object_id, version) REFERENCES versions (object_id, version) ON DELETE CASCADE
);
CREATE INDEX part_parameters_range ON part_parameters (name, support_lo, support_hi);

CREATE TABLE csg_nodes (
  object_id BIGINT NOT NULL,
  version INTEGER NOT NULL,
  node INTEGER NOT NULL,
  parent INTEGER NOT NULL,
  position INTEGER NOT NULL,
  kind TEXT COLLATE "C" NOT NULL,
  operator TEXT,
  ref_id BIGINT,
  transform TEXT,
  PRIMARY KEY (object_id, version, node),
  FOREIGN KEY (object_id, version) REFERENCES versions (object_id, version) ON DELETE CASCADE
);

CREATE TABLE eval_cache (
  key TEXT COLLATE "C" PRIMARY KEY,
  object_id BIGINT NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  result TEXT NOT NULL,
  vdb BYTEA
);
CREATE INDEX eval_cache_object ON eval_cache (object_id);
