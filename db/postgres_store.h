#pragma once
// PostgresStore: Store (db/store.h) on one PostgreSQL database over libpq
// (`--db postgresql://user@host:port/database[?schema=NAME]`), for several stateless fsdb servers
// sharing one catalogue. Writers of all servers take one advisory lock per schema (db/postgres.h),
// readers see REPEATABLE READ snapshots; a connection the server dropped is opened again before
// its next use. Migrations: schema/migrations/postgresql/*.sql, version in the table fsdb_schema.
#include <memory>
#include <string>

#include "db/sql_store.h"

namespace fsdb {

namespace postgres {
struct Address;
}

class PostgresStore final : public SqlStore {
 public:
  // Connects (poolSize connections), creates the URL's schema when missing and migrates.
  // storage_error naming the URL (password hidden) when the server cannot be reached.
  static std::unique_ptr<Store> open(const std::string& url, const StoreOptions& options = {});

  std::string backend() const override { return "postgresql"; }
  void checkpoint() override {}  // the server owns durability
  // The store's own invariants: every object has its latest version and every edge's ends live.
  std::string integrityCheck() const override;

 private:
  using SqlStore::SqlStore;
  void beforeUse(sql::Connection& connection) const override;
};

}  // namespace fsdb
