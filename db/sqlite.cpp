// See db/sqlite.h.
#include "db/sqlite.h"

#include <sqlite3.h>

#include "geometry/core/error.h"

namespace fsdb::sqlite {

void fail(sqlite3* db, const std::string& what) {
  std::string message = db ? sqlite3_errmsg(db) : "out of memory";
  throw Error(errc::kStorage, what + " failed: " + message);
}

// --- Statement ---------------------------------------------------------------------------------

Statement::Statement(sqlite3* db, const std::string& sql) : db_(db), sql_(sql) {
  if (sqlite3_prepare_v2(db_, sql.c_str(), static_cast<int>(sql.size() + 1), &stmt_, nullptr) != SQLITE_OK) {
    sqlite3_finalize(stmt_);
    fail(db_, "prepare of '" + sql + "'");
  }
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

namespace {
void checkBind(sqlite3* db, int rc, int index) {
  if (rc != SQLITE_OK) fail(db, "bind of parameter " + std::to_string(index));
}
}  // namespace

sql::Statement& Statement::bind(int index, int64_t value) {
  checkBind(db_, sqlite3_bind_int64(stmt_, index, value), index);
  return *this;
}

sql::Statement& Statement::bind(int index, double value) {
  checkBind(db_, sqlite3_bind_double(stmt_, index, value), index);
  return *this;
}

sql::Statement& Statement::bind(int index, const std::string& text) {
  checkBind(db_, sqlite3_bind_text64(stmt_, index, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8), index);
  return *this;
}

sql::Statement& Statement::bindBlob(int index, const std::string& bytes) {
  checkBind(db_, sqlite3_bind_blob64(stmt_, index, bytes.data(), bytes.size(), SQLITE_TRANSIENT), index);
  return *this;
}

sql::Statement& Statement::bindNull(int index) {
  checkBind(db_, sqlite3_bind_null(stmt_, index), index);
  return *this;
}

bool Statement::step() {
  int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  // sqlite3_errmsg still holds the step's message until the next call on this connection.
  std::string what = "'" + sql_ + "'";
  fail(db_, what);
}

void Statement::reset() {
  // The return code of reset repeats the last step's error, already reported by step().
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::isNull(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }

int64_t Statement::columnInt(int column) const { return sqlite3_column_int64(stmt_, column); }

double Statement::columnDouble(int column) const { return sqlite3_column_double(stmt_, column); }

std::string Statement::columnText(int column) const {
  const unsigned char* text = sqlite3_column_text(stmt_, column);
  int size = sqlite3_column_bytes(stmt_, column);
  return text ? std::string(reinterpret_cast<const char*>(text), static_cast<size_t>(size)) : "";
}

std::string Statement::columnBlob(int column) const {
  const void* bytes = sqlite3_column_blob(stmt_, column);
  int size = sqlite3_column_bytes(stmt_, column);
  return bytes ? std::string(static_cast<const char*>(bytes), static_cast<size_t>(size)) : "";
}

// --- Connection --------------------------------------------------------------------------------

Connection::Connection(const std::string& path, const ConnectionOptions& options) {
  // NOMUTEX: the pool gives a connection to one thread at a time, so SQLite's own per-connection
  // mutex would only cost time.
  int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw Error(errc::kStorage, "open of '" + path + "' failed: " + message);
  }
  try {
    sqlite3_extended_result_codes(db_, 1);
    sqlite3_busy_timeout(db_, options.busyTimeoutMs);
    exec("PRAGMA journal_mode = WAL");
    exec("PRAGMA foreign_keys = ON");
    exec(options.synchronousFull ? "PRAGMA synchronous = FULL" : "PRAGMA synchronous = NORMAL");
    // 64 MiB of page cache (the default is 2 MiB): index range scans of a large catalogue then
    // read their pages from memory instead of one pread per page.
    exec("PRAGMA cache_size = -65536");
    // Savepoints (one per bulk-import line) journal every page they first touch; in a file,
    // that was a pwrite per page and a third of an import's time (docs/performance.md).
    exec("PRAGMA temp_store = MEMORY");
    exec("PRAGMA journal_size_limit = " + std::to_string(kWalSizeLimitBytes));
    busyTimeoutMs_ = options.busyTimeoutMs;
    // Replaces SQLite's automatic checkpoint (a WAL hook of its own) with onWalCommit.
    sqlite3_wal_hook(db_, &Connection::onWalCommit, this);
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

Connection::~Connection() {
  statements_.clear();  // finalize before close, else sqlite3_close refuses
  sqlite3_close(db_);
}

// Why RESTART: a PASSIVE checkpoint copies only the frames older than every reader's snapshot, and
// the WAL starts over only when no reader uses it. Under a steady stream of reads some reader
// always does, so with SQLite's automatic checkpoint alone the WAL grew without bound (200-445
// MiB in the 80 s soak, bench/soak.sh), and every read searched a longer WAL index. RESTART waits
// for the readers of older snapshots (they finish in milliseconds); readers that start once every
// frame is copied read the database file, so the next commit writes the WAL from its start. The
// wait is short and tried once per 1000 frames: a long read (an export's snapshot) costs a commit
// at most kWalRestartWaitMs, and the WAL only grows until that read ends.
int Connection::onWalCommit(void* self, sqlite3* db, const char* name, int frames) {
  auto* connection = static_cast<Connection*>(self);
  if (frames < kWalRestartFrames) connection->lastRestartAttempt_ = 0;  // the WAL started over
  if (frames < 1000) return SQLITE_OK;
  if (frames < kWalRestartFrames || frames / 1000 == connection->lastRestartAttempt_) {
    sqlite3_wal_checkpoint_v2(db, name, SQLITE_CHECKPOINT_PASSIVE, nullptr, nullptr);
    return SQLITE_OK;
  }
  connection->lastRestartAttempt_ = frames / 1000;
  sqlite3_busy_timeout(db, kWalRestartWaitMs);
  sqlite3_wal_checkpoint_v2(db, name, SQLITE_CHECKPOINT_RESTART, nullptr, nullptr);
  sqlite3_busy_timeout(db, connection->busyTimeoutMs_);
  // The commit has happened whatever the checkpoint answered (SQLITE_BUSY when a reader stayed);
  // an error here would only be reported as the commit's.
  return SQLITE_OK;
}

void Connection::exec(const std::string& sql) {
  // One statement (SAVEPOINT, RELEASE, BEGIN, COMMIT: several per bulk-import line) runs from
  // the statement cache instead of being parsed again each time; scripts go to sqlite3_exec.
  if (sql.find(';') == std::string::npos) {
    prepare(sql)->run();
    return;
  }
  char* message = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    std::string text = message ? message : sqlite3_errmsg(db_);
    sqlite3_free(message);
    throw Error(errc::kStorage, "'" + sql.substr(0, 80) + "' failed: " + text);
  }
}

StatementRef Connection::prepare(const std::string& sql) {
  auto found = statements_.find(sql);
  if (found == statements_.end()) found = statements_.emplace(sql, std::make_unique<Statement>(db_, sql)).first;
  return StatementRef(*found->second);
}

int64_t Connection::lastInsertId() const { return sqlite3_last_insert_rowid(db_); }

int Connection::changes() const { return sqlite3_changes(db_); }

bool Connection::inTransaction() const { return sqlite3_get_autocommit(db_) == 0; }

void Connection::begin(sql::TransactionMode mode) {
  exec(mode == sql::TransactionMode::kWrite ? "BEGIN IMMEDIATE" : "BEGIN DEFERRED");
}

void Connection::rollbackQuietly() {
  // Some errors (disk full, I/O) end the transaction themselves; ROLLBACK would then fail.
  if (inTransaction()) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

int Connection::schemaVersion() {
  auto statement = prepare("PRAGMA user_version");
  return statement->step() ? static_cast<int>(statement->columnInt(0)) : 0;
}

void Connection::setSchemaVersion(int version) {
  // PRAGMA takes no bound parameters; the value is our own integer, not input.
  exec("PRAGMA user_version = " + std::to_string(version));
}

}  // namespace fsdb::sqlite
