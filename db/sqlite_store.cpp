// See db/sqlite_store.h.
#include "db/sqlite_store.h"

#include <algorithm>
#include <filesystem>

#include "db/migrations.h"
#include "db/sqlite.h"
#include "geometry/core/error.h"

namespace fsdb {

std::unique_ptr<Store> SqliteStore::open(const std::string& path, const StoreOptions& options) {
  if (path.empty() || path == ":memory:" || path.rfind("file:", 0) == 0)
    throw Error(errc::kStorage, "store path '" + path + "' is not a file path");
  std::error_code error;
  auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  if (error) throw Error(errc::kStorage, "cannot create the directory of '" + path + "': " + error.message());
  std::unique_ptr<SqliteStore> store(new SqliteStore(path));
  sqlite::ConnectionOptions connectionOptions{options.busyTimeoutMs, options.synchronousFull};
  // The first connection migrates before the others open, so none of them sees an old schema.
  for (int i = 0; i < std::max(1, options.poolSize); ++i) {
    auto connection = std::make_unique<sqlite::Connection>(path, connectionOptions);
    if (i == 0) store->setSchemaVersion(applyMigrations(*connection, embeddedMigrations()));
    store->addConnection(std::move(connection));
  }
  store->setMaxCacheBytes(options.maxCacheBytes);
  return store;
}

void SqliteStore::checkpoint() {
  Lease connection(*this, Lease::Use::kOwn);
  auto statement = (*connection).prepare("PRAGMA wal_checkpoint(TRUNCATE)");
  statement->run();
}

std::string SqliteStore::integrityCheck() const {
  Lease connection(*this);
  auto statement = (*connection).prepare("PRAGMA integrity_check");
  return statement->step() ? statement->columnText(0) : "no result";
}

}  // namespace fsdb
