#pragma once
// The SQLite engine of db/sql.h: a thin RAII layer over the SQLite C API, used only by db/.
//
// Contract (beyond db/sql.h)
// - Every SQLite failure becomes fsdb::Error(errc::kStorage, "<what> failed: <sqlite message>").
// - A connection opens in WAL mode with foreign keys on and a busy timeout; kWrite transactions
//   are BEGIN IMMEDIATE (the write lock is taken at once, so a transaction cannot fail later on a
//   lock upgrade), kRead ones BEGIN DEFERRED.
// - A borrowed cached statement is reset when the borrow ends: a statement left mid-result would
//   keep a read transaction open, pinning an old WAL snapshot and blocking checkpoints.
// - The schema version is PRAGMA user_version.
// - The WAL stays bounded under reads that never stop: SQLite's own checkpoint every 1000 frames
//   (PASSIVE) runs as before, and once the WAL holds kWalRestartFrames frames a commit also
//   checkpoints in RESTART mode (waiting at most kWalRestartWaitMs for the readers of older
//   snapshots), so that the next commit writes the WAL from its start; a WAL file left larger
//   than kWalSizeLimitBytes is cut back to it when the WAL starts over (journal_size_limit).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "db/sql.h"

struct sqlite3;
struct sqlite3_stmt;

namespace fsdb::sqlite {

using sql::Savepoint;
using sql::StatementRef;
using sql::Transaction;

// Throws Error(kStorage, what + " failed: " + sqlite3_errmsg(db)).
[[noreturn]] void fail(sqlite3* db, const std::string& what);

class Statement final : public sql::Statement {
 public:
  Statement(sqlite3* db, const std::string& sql);
  ~Statement() override;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  using sql::Statement::bind;
  sql::Statement& bind(int index, int64_t value) override;
  sql::Statement& bind(int index, double value) override;
  sql::Statement& bind(int index, const std::string& text) override;
  sql::Statement& bindBlob(int index, const std::string& bytes) override;
  sql::Statement& bindNull(int index) override;
  bool step() override;
  void reset() override;
  bool isNull(int column) const override;
  int64_t columnInt(int column) const override;
  double columnDouble(int column) const override;
  std::string columnText(int column) const override;
  std::string columnBlob(int column) const override;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;  // for error messages
};

// Frames (pages) in the WAL from which a commit checkpoints in RESTART mode: 16 MiB of 4 KiB pages.
constexpr int kWalRestartFrames = 4096;
// How long that commit waits for the readers of older snapshots before it gives up until the WAL
// has grown by another 1000 frames.
constexpr int kWalRestartWaitMs = 100;
constexpr int64_t kWalSizeLimitBytes = int64_t{64} << 20;

struct ConnectionOptions {
  int busyTimeoutMs = 5000;
  bool synchronousFull = false;  // PRAGMA synchronous = FULL instead of NORMAL
};

class Connection final : public sql::Connection {
 public:
  // Opens (creating when missing) in WAL mode with foreign keys on. Fails with kStorage naming
  // the path.
  Connection(const std::string& path, const ConnectionOptions& options = {});
  ~Connection() override;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  sql::Dialect dialect() const override { return sql::Dialect::kSqlite; }
  void exec(const std::string& sql) override;
  StatementRef prepare(const std::string& sql) override;
  bool inTransaction() const override;
  void begin(sql::TransactionMode mode) override;
  void rollbackQuietly() override;
  int schemaVersion() override;
  void setSchemaVersion(int version) override;

  int64_t lastInsertId() const;
  int changes() const;  // rows changed by the last INSERT/UPDATE/DELETE
  sqlite3* handle() const { return db_; }

 private:
  sqlite3* db_ = nullptr;
  int busyTimeoutMs_ = 0;
  int lastRestartAttempt_ = 0;  // WAL frames at this connection's last RESTART checkpoint, in thousands
  static int onWalCommit(void* connection, sqlite3* db, const char* name, int frames);
  std::unordered_map<std::string, std::unique_ptr<Statement>> statements_;
};

}  // namespace fsdb::sqlite
