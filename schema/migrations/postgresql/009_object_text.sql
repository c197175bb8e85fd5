-- 009_object_text for PostgreSQL: as schema/migrations/009_object_text.sql, the words of each part
-- and shape (name, meta.description, descriptors) for the search box, as a tsvector of the
-- 'english' configuration (stemmed, without stop words) with a GIN index; the row goes with its
-- object (ON DELETE CASCADE).
CREATE TABLE object_text (
  object_id BIGINT PRIMARY KEY REFERENCES objects (id) ON DELETE CASCADE,
  words tsvector NOT NULL
);
CREATE INDEX object_text_words ON object_text USING GIN (words);
INSERT INTO object_text (object_id, words)
  SELECT o.id, to_tsvector('english', o.name
      || CASE WHEN jsonb_typeof(v.document::jsonb -> 'meta' -> 'description') = 'string'
              THEN ' ' || (v.document::jsonb -> 'meta' ->> 'description') ELSE '' END
      || COALESCE((SELECT ' ' || string_agg(d #>> '{}', ' ') FROM jsonb_array_elements(
                     CASE WHEN jsonb_typeof(v.document::jsonb -> 'descriptors') = 'array'
                          THEN v.document::jsonb -> 'descriptors' ELSE '[]'::jsonb END) d
                   WHERE jsonb_typeof(d) = 'string'), ''))
  FROM objects o JOIN versions v ON v.object_id = o.id AND v.version = o.latest_version
  WHERE o.kind IN ('part', 'shape');
