-- 009_object_text: the words a part or shape is described by, for the search box (POST /query):
-- its name, its meta.description and its descriptors (the document's list of words), in an FTS5
-- table whose rowid is the object's id, stemmed (porter) and without accents. The store writes
-- the row with every version (db/object_rows.cpp, objectText); deleting the object deletes it.
-- detail=none, columnsize=0: the search asks only whether every word is there (no phrases, no
-- ranking by frequency), so no positions and no document sizes are kept: every version writes
-- fewer pages (the soak's RSS grew past its bound with them).
CREATE VIRTUAL TABLE object_text USING fts5(words, tokenize = 'porter unicode61 remove_diacritics 2',
                                             detail = none, columnsize = 0);
CREATE TRIGGER object_text_deleted AFTER DELETE ON objects BEGIN
  DELETE FROM object_text WHERE rowid = old.id;
END;
-- The objects stored before: the same words objectText writes (name, description, descriptors).
INSERT INTO object_text (rowid, words)
  SELECT o.id, o.name
      || CASE WHEN json_type(v.document, '$.meta.description') = 'text'
              THEN ' ' || json_extract(v.document, '$.meta.description') ELSE '' END
      || COALESCE((SELECT ' ' || group_concat(d.value, ' ') FROM json_each(v.document, '$.descriptors') d
                   WHERE d.type = 'text'), '')
  FROM objects o JOIN versions v ON v.object_id = o.id AND v.version = o.latest_version
  WHERE o.kind IN ('part', 'shape') AND json_valid(v.document);
