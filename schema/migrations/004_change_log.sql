-- 004_change_log: the store-wide change log (db/store.h changesSince). Every write appends the id
-- of each object it created, changed or deleted under the next sequence number, inside the write
-- transaction; writers hold the database's write lock, so sequence numbers commit in order and a
-- reader that has seen seq N has seen every change up to N. A server's in-memory caches (the
-- structural search's graphs) ask for the changes after the last seq they saw, instead of reading
-- every object's version per query, and so see writes made through other servers on the same
-- database. The writer keeps the newest 100000 entries; a reader older than that starts over.
-- AUTOINCREMENT: a sequence number is never reused, even after the newest entries are pruned.
CREATE TABLE change_log (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  object_id INTEGER NOT NULL
);
