// See db/postgres_store.h.
#include "db/postgres_store.h"

#include <algorithm>

#include "db/migrations.h"
#include "db/postgres.h"
#include "geometry/core/error.h"

namespace fsdb {

std::unique_ptr<Store> PostgresStore::open(const std::string& url, const StoreOptions& options) {
  const postgres::Address address = postgres::parseAddress(url);
  std::unique_ptr<PostgresStore> store(new PostgresStore(address.display));
  for (int i = 0; i < std::max(1, options.poolSize); ++i) {
    auto connection = std::make_unique<postgres::Connection>(address);
    if (i == 0) {
      connection->prepareSchema();
      store->setSchemaVersion(applyMigrations(*connection, embeddedPostgresMigrations()));
    }
    store->addConnection(std::move(connection));
  }
  store->setMaxCacheBytes(options.maxCacheBytes);
  return store;
}

void PostgresStore::beforeUse(sql::Connection& connection) const {
  auto& pg = static_cast<postgres::Connection&>(connection);
  if (pg.broken()) pg.reconnect();
}

std::string PostgresStore::integrityCheck() const {
  Lease connection(*this);
  static const char* const kChecks[][2] = {
      {"an object without its latest version",
       "SELECT o.id FROM objects o LEFT JOIN versions v ON v.object_id = o.id AND v.version = o.latest_version"
       " WHERE v.object_id IS NULL LIMIT 1"},
      {"an edge to a deleted object",
       "SELECT r.parent_id FROM refs r LEFT JOIN objects o ON o.id = r.child_id WHERE o.id IS NULL LIMIT 1"},
  };
  for (const auto& check : kChecks) {
    auto statement = (*connection).prepare(check[1]);
    if (statement->step()) return std::string(check[0]) + " (id " + std::to_string(statement->columnInt(0)) + ")";
  }
  return "ok";
}

}  // namespace fsdb
