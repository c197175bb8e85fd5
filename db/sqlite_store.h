#pragma once
// SqliteStore: Store (db/store.h) on one embedded SQLite file, the default backend (`--db PATH`).
// WAL journal, foreign keys on, a busy timeout (StoreOptions::busyTimeoutMs); readers run beside
// the one writer. Migrations: schema/migrations/*.sql, version in PRAGMA user_version.
#include <memory>
#include <string>

#include "db/sql_store.h"

namespace fsdb {

class SqliteStore final : public SqlStore {
 public:
  // Opens `path` (creating it, with parent directories, when missing) and migrates. storage_error
  // for ":memory:", "file:" URIs and files SQLite cannot open.
  static std::unique_ptr<Store> open(const std::string& path, const StoreOptions& options = {});

  std::string backend() const override { return "sqlite"; }
  // PRAGMA wal_checkpoint(TRUNCATE): the WAL folded into the file, so it is whole on its own.
  void checkpoint() override;
  // PRAGMA integrity_check.
  std::string integrityCheck() const override;

 private:
  using SqlStore::SqlStore;
};

}  // namespace fsdb
