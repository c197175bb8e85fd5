// See db/migrations.h.
#include "db/migrations.h"

#include <algorithm>

#include "db/sql.h"
#include "geometry/core/error.h"

namespace fsdb {

int schemaVersionOf(sql::Connection& connection) { return connection.schemaVersion(); }

int applyMigrations(sql::Connection& connection,
                    const std::vector<std::pair<int, std::string>>& migrations) {
  auto sorted = migrations;
  std::sort(sorted.begin(), sorted.end());
  int known = sorted.empty() ? 0 : sorted.back().first;
  int current = schemaVersionOf(connection);
  if (current > known)
    throw Error(errc::kStorage, "database schema version " + std::to_string(current) +
                                    " is newer than this fsdb knows (" + std::to_string(known) +
                                    "); upgrade fsdb to open it");
  for (const auto& [version, text] : sorted) {
    if (version <= current) continue;
    sql::Transaction transaction(connection);
    // Re-read under the write lock: another process may have migrated since we looked.
    if (schemaVersionOf(connection) >= version) continue;
    try {
      connection.exec(text);
    } catch (const Error& e) {
      throw Error(errc::kStorage, "migration " + std::to_string(version) + ": " + e.what());
    }
    connection.setSchemaVersion(version);
    transaction.commit();
    current = version;
  }
  return schemaVersionOf(connection);
}

}  // namespace fsdb
