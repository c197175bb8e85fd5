-- 002_descriptor_index for PostgreSQL: the tables of schema/migrations/002_descriptor_index.sql
-- (read the reasons there) in PostgreSQL's types.
CREATE TABLE descriptor_index (
  object_id BIGINT NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  kind TEXT COLLATE "C" NOT NULL,
  component INTEGER NOT NULL,
  descriptor TEXT COLLATE "C" NOT NULL,
  width_class INTEGER NOT NULL,
  support_lo DOUBLE PRECISION NOT NULL,
  core_lo DOUBLE PRECISION NOT NULL,
  core_hi DOUBLE PRECISION NOT NULL,
  support_hi DOUBLE PRECISION NOT NULL,
  PRIMARY KEY (object_id, component, descriptor)
);
CREATE INDEX descriptor_index_overlap
  ON descriptor_index (kind, descriptor, width_class, support_lo, support_hi);

CREATE TABLE descriptor_classes (
  descriptor TEXT COLLATE "C" NOT NULL,
  width_class INTEGER NOT NULL,
  PRIMARY KEY (descriptor, width_class)
);

CREATE TABLE descriptor_values (
  object_id BIGINT NOT NULL REFERENCES objects (id) ON DELETE CASCADE,
  component INTEGER NOT NULL,
  descriptor_values BYTEA NOT NULL,
  PRIMARY KEY (object_id, component)
);

CREATE TABLE descriptor_pending (
  object_id BIGINT PRIMARY KEY REFERENCES objects (id) ON DELETE CASCADE,
  generation BIGINT NOT NULL
);
CREATE TABLE descriptor_clock (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  generation BIGINT NOT NULL
);
INSERT INTO descriptor_clock (id, generation) VALUES (1, 1);

INSERT INTO descriptor_pending (object_id, generation)
  SELECT id, 1 FROM objects WHERE kind IN ('part', 'shape');
