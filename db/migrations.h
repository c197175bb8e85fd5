#pragma once
// Schema migrations: schema/migrations/NNN_name.sql for SQLite and
// schema/migrations/postgresql/NNN_name.sql for PostgreSQL (the same versions, each in its
// engine's SQL), compiled into the binary by db/migrations_embed.cmake. The database records the
// highest migration applied (sql::Connection::schemaVersion: SQLite's PRAGMA user_version, a
// one-row table fsdb_schema on PostgreSQL).
//
// Contract
// - applyMigrations applies, in increasing version order, each migration newer than
//   the database's version, each in its own write transaction that also records the version, so
//   a failed migration leaves the database at the previous version, and two processes opening the
//   same new database do not both apply it.
// - A database whose version is newer than every migration given is refused
//   (storage_error): this binary does not know its schema.
#include <string>
#include <utility>
#include <vector>

namespace fsdb {

namespace sql {
class Connection;
}

// (version, SQL text) of every schema/migrations/*.sql, sorted by version.
const std::vector<std::pair<int, std::string>>& embeddedMigrations();
// The same for PostgreSQL: schema/migrations/postgresql/*.sql.
const std::vector<std::pair<int, std::string>>& embeddedPostgresMigrations();

// The database's schema version (0 for a new database).
int schemaVersionOf(sql::Connection& connection);

// Applies `migrations` (any order; versions unique and > 0) newer than the database's version.
// Returns the resulting version.
int applyMigrations(sql::Connection& connection,
                    const std::vector<std::pair<int, std::string>>& migrations);

}  // namespace fsdb
