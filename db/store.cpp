// See db/store.h: Store::open picks the backend from the location.
#include "db/store.h"

#include "db/postgres.h"
#include "db/postgres_store.h"
#include "db/sqlite_store.h"

namespace fsdb {

std::unique_ptr<Store> Store::open(const std::string& location, const StoreOptions& options) {
  if (postgres::isPostgresUrl(location)) return PostgresStore::open(location, options);
  return SqliteStore::open(location, options);
}

}  // namespace fsdb
