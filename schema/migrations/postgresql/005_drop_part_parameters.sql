-- 005_drop_part_parameters for PostgreSQL: as schema/migrations/005_drop_part_parameters.sql
-- (read the reasons there); the index goes with its table.
DROP TABLE IF EXISTS part_parameters;
