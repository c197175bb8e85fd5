#pragma once
// A thin RAII layer over the SQLite C API, used only by db/.
//
// Contract
// - Every SQLite failure becomes fsdb::Error(errc::kStorage, "<what> failed: <sqlite message>"),
//   so the service answers 503 storage_error and never sees an SQLite return code.
// - Values reach SQL only through bound parameters (Statement::bind*); Connection::exec is for
//   constant SQL written in this repository (pragmas, migrations, BEGIN/COMMIT).
// - A Connection is used by one thread at a time (the store's pool hands it out); it caches its
//   prepared statements by SQL text, so hot paths (get by id) prepare once per connection.
// - A borrowed cached statement (Connection::prepare) is reset when the borrow ends: a statement
//   left mid-result would keep a read transaction open, pinning an old WAL snapshot and blocking
//   checkpoints.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

struct sqlite3;
struct sqlite3_stmt;

namespace fsdb::sqlite {

// Throws Error(kStorage, what + " failed: " + sqlite3_errmsg(db)).
[[noreturn]] void fail(sqlite3* db, const std::string& what);

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Parameters are numbered from 1, as in SQLite.
  Statement& bind(int index, int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, const std::string& text);
  Statement& bind(int index, const char* text) { return bind(index, std::string(text)); }
  Statement& bind(int index, const std::optional<int64_t>& value);  // nullopt binds NULL
  Statement& bindBlob(int index, const std::string& bytes);  // empty binds a zero-length blob
  Statement& bindNull(int index);

  // true: a row is available (read it with the column getters); false: done.
  bool step();
  // Steps to the end, for statements that return no rows (INSERT, UPDATE, DELETE).
  void run();
  // Ready to run again: resets and clears the bindings.
  void reset();

  // Columns are numbered from 0, as in SQLite.
  bool isNull(int column) const;
  int64_t columnInt(int column) const;
  double columnDouble(int column) const;
  std::string columnText(int column) const;  // "" for NULL
  std::string columnBlob(int column) const;  // "" for NULL
  std::optional<int64_t> columnOptionalInt(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;  // for error messages
};

// A cached statement on loan from its connection: use it like a pointer; reset on destruction.
class StatementRef {
 public:
  explicit StatementRef(Statement& statement) : statement_(&statement) {}
  ~StatementRef() { statement_->reset(); }
  StatementRef(const StatementRef&) = delete;
  StatementRef& operator=(const StatementRef&) = delete;
  Statement* operator->() const { return statement_; }
  Statement& operator*() const { return *statement_; }

 private:
  Statement* statement_;
};

struct ConnectionOptions {
  int busyTimeoutMs = 5000;
  bool synchronousFull = false;  // PRAGMA synchronous = FULL instead of NORMAL
};

class Connection {
 public:
  // Opens (creating when missing) in WAL mode with foreign keys on. Fails with kStorage naming
  // the path.
  Connection(const std::string& path, const ConnectionOptions& options = {});
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Runs constant SQL (one or more statements; result rows are ignored).
  void exec(const std::string& sql);
  // The cached statement for `sql`, prepared on first use.
  StatementRef prepare(const std::string& sql);
  int64_t lastInsertId() const;
  int changes() const;        // rows changed by the last INSERT/UPDATE/DELETE
  bool inTransaction() const;  // false in autocommit mode
  sqlite3* handle() const { return db_; }

 private:
  sqlite3* db_ = nullptr;
  std::unordered_map<std::string, std::unique_ptr<Statement>> statements_;
};

// BEGIN IMMEDIATE (writes: takes the write lock now, so the transaction cannot fail later on a
// lock upgrade) or BEGIN DEFERRED (consistent reads). Rolls back on destruction unless committed.
class Transaction {
 public:
  enum class Mode { kImmediate, kDeferred };
  explicit Transaction(Connection& connection, Mode mode = Mode::kImmediate);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Connection& connection_;
  bool done_ = false;
};

// A nested unit inside a transaction: release() keeps its changes; otherwise destruction rolls
// back to the savepoint (and releases it), leaving the enclosing transaction alive.
class Savepoint {
 public:
  Savepoint(Connection& connection, std::string name);  // name: an identifier from code
  ~Savepoint();
  Savepoint(const Savepoint&) = delete;
  Savepoint& operator=(const Savepoint&) = delete;
  void release();
  void rollback();  // undo and release now

 private:
  Connection& connection_;
  std::string name_;
  bool done_ = false;
};

}  // namespace fsdb::sqlite
