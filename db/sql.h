#pragma once
// The SQL connection that the store's queries run on, apart from the engine that runs them:
// db/sqlite.h (an embedded SQLite file) and db/postgres.h (a PostgreSQL server over libpq)
// implement it, and db/sql_store.h writes every query of the store once, against this interface.
//
// Contract
// - SQL text uses numbered parameters ?1, ?2, ... (SQLite's form); the PostgreSQL connection
//   rewrites them to $1, $2, ... when it prepares. Only SQL both engines accept goes through
//   prepare(); where they differ the caller asks dialect() (docs/design/storage-backends.md).
// - Every engine failure becomes fsdb::Error(errc::kStorage, ...) (HTTP 503 storage_error).
// - A connection is used by one thread at a time (the store's pool hands it out) and caches its
//   prepared statements by SQL text; a borrowed statement is reset when the borrow ends.
// - Transactions: kWrite serialises writers against every other writer of the same database
//   (SQLite: BEGIN IMMEDIATE; PostgreSQL: a transaction-scoped advisory lock), so the checks a
//   write makes (names, cycles) cannot race; kRead gives one consistent snapshot.
#include <cstdint>
#include <optional>
#include <string>

namespace fsdb::sql {

enum class Dialect { kSqlite, kPostgres };

class Statement {
 public:
  virtual ~Statement() = default;

  // Parameters are numbered from 1.
  virtual Statement& bind(int index, int64_t value) = 0;
  Statement& bind(int index, int value) { return bind(index, static_cast<int64_t>(value)); }
  virtual Statement& bind(int index, double value) = 0;
  virtual Statement& bind(int index, const std::string& text) = 0;
  Statement& bind(int index, const char* text) { return bind(index, std::string(text)); }
  Statement& bind(int index, const std::optional<int64_t>& value) {
    return value ? bind(index, *value) : bindNull(index);
  }
  virtual Statement& bindBlob(int index, const std::string& bytes) = 0;  // empty binds a zero-length blob
  virtual Statement& bindNull(int index) = 0;

  // true: a row is available (read it with the column getters); false: done.
  virtual bool step() = 0;
  // Steps to the end, for statements that return no rows (INSERT, UPDATE, DELETE).
  void run() {
    while (step()) {
    }
  }
  // Ready to run again: resets and clears the bindings.
  virtual void reset() = 0;

  // Columns are numbered from 0.
  virtual bool isNull(int column) const = 0;
  virtual int64_t columnInt(int column) const = 0;
  virtual double columnDouble(int column) const = 0;
  virtual std::string columnText(int column) const = 0;  // "" for NULL
  virtual std::string columnBlob(int column) const = 0;  // "" for NULL
  std::optional<int64_t> columnOptionalInt(int column) const {
    if (isNull(column)) return std::nullopt;
    return columnInt(column);
  }
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

// "(?1, ?2), (?3, ?4)" for rows = 2, columns = 2: the VALUES of a multi-row INSERT. One statement
// writes many rows in one round trip to the server (a part's descriptor rows: 13 in one).
inline std::string rowPlaceholders(int rows, int columns) {
  std::string out;
  for (int r = 0, n = 1; r < rows; ++r) {
    out += r ? ", (" : "(";
    for (int c = 0; c < columns; ++c, ++n) out += (c ? ", ?" : "?") + std::to_string(n);
    out += ")";
  }
  return out;
}

// "?2, ?3, ?4" for first = 2, count = 3: the list of an IN (...) that a statement binds ids to.
inline std::string listPlaceholders(int first, int count) {
  std::string out;
  for (int i = 0; i < count; ++i) out += (i ? ", ?" : "?") + std::to_string(first + i);
  return out;
}

// The rows of a multi-row statement go in chunks of at most this many, so a connection caches at
// most this many variants of one statement (one per chunk size).
constexpr int kRowsPerStatement = 32;

enum class TransactionMode { kWrite, kRead };

class Connection {
 public:
  virtual ~Connection() = default;
  virtual Dialect dialect() const = 0;
  // Runs constant SQL written in this repository (one or more statements; rows are ignored).
  virtual void exec(const std::string& sql) = 0;
  // The cached statement for `sql`, prepared on first use.
  virtual StatementRef prepare(const std::string& sql) = 0;
  // false in autocommit mode, and after an error that ended the transaction by itself.
  virtual bool inTransaction() const = 0;
  virtual void begin(TransactionMode mode) = 0;
  // Rolls back without throwing (destructors call it).
  virtual void rollbackQuietly() = 0;
  // The highest migration applied, and recording a new one (inside the migration's transaction).
  virtual int schemaVersion() = 0;
  virtual void setSchemaVersion(int version) = 0;
};

// A transaction, rolled back on destruction unless committed. A read transaction begun on a
// connection already in one (Store::readSnapshot's) joins it: it neither begins nor ends it.
class Transaction {
 public:
  using Mode = TransactionMode;
  explicit Transaction(Connection& connection, Mode mode = Mode::kWrite) : connection_(connection) {
    if (mode == Mode::kRead && connection_.inTransaction()) {
      done_ = joined_ = true;
      return;
    }
    connection_.begin(mode);
  }
  ~Transaction() {
    if (!done_ && connection_.inTransaction()) connection_.rollbackQuietly();
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    if (joined_) return;
    connection_.exec("COMMIT");
    done_ = true;
  }

 private:
  Connection& connection_;
  bool done_ = false;
  bool joined_ = false;
};

// A nested unit inside a transaction: release() keeps its changes; otherwise destruction rolls
// back to the savepoint (and releases it), leaving the enclosing transaction alive (on
// PostgreSQL this also clears the transaction's error state after a failed statement).
class Savepoint {
 public:
  Savepoint(Connection& connection, std::string name)  // name: an identifier from code
      : connection_(connection), name_(std::move(name)) {
    connection_.exec("SAVEPOINT " + name_);
  }
  ~Savepoint() {
    if (done_ || !connection_.inTransaction()) return;
    try {
      rollback();
    } catch (...) {  // the enclosing transaction's destructor rolls everything back
    }
  }
  Savepoint(const Savepoint&) = delete;
  Savepoint& operator=(const Savepoint&) = delete;
  void release() {
    connection_.exec("RELEASE SAVEPOINT " + name_);
    done_ = true;
  }
  void rollback() {  // undo and release now
    done_ = true;
    connection_.exec("ROLLBACK TO SAVEPOINT " + name_);
    connection_.exec("RELEASE SAVEPOINT " + name_);
  }

 private:
  Connection& connection_;
  std::string name_;
  bool done_ = false;
};

}  // namespace fsdb::sql
