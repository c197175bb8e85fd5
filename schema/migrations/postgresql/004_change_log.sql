-- 004_change_log for PostgreSQL: as schema/migrations/004_change_log.sql (read the reasons there).
-- An identity sequence hands out numbers outside transactions, so a rolled-back write leaves a gap;
-- the order of the numbers that commit is the commit order, because every writer holds the
-- schema's advisory lock from before it takes a number until it commits (db/postgres.h).
CREATE TABLE change_log (
  seq BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  object_id BIGINT NOT NULL
);
