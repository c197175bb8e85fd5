#pragma once
// Schema migrations: schema/migrations/NNN_name.sql, compiled into the binary by
// db/migrations_embed.cmake. The database's PRAGMA user_version is the highest migration applied.
//
// Contract
// - applyMigrations applies, in increasing version order, each migration newer than
//   user_version, each in its own BEGIN IMMEDIATE transaction that also sets user_version, so a
//   failed migration leaves the database at the previous version, and two processes opening the
//   same new file do not both apply it.
// - A database whose user_version is newer than every migration given is refused
//   (storage_error): this binary does not know its schema.
#include <string>
#include <utility>
#include <vector>

namespace fsdb {

namespace sqlite {
class Connection;
}

// (version, SQL text) of every schema/migrations/*.sql, sorted by version.
const std::vector<std::pair<int, std::string>>& embeddedMigrations();

// The database's PRAGMA user_version.
int schemaVersionOf(sqlite::Connection& connection);

// Applies `migrations` (any order; versions unique and > 0) newer than the database's version.
// Returns the resulting version.
int applyMigrations(sqlite::Connection& connection,
                    const std::vector<std::pair<int, std::string>>& migrations);

}  // namespace fsdb
