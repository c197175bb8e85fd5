#pragma once
// The PostgreSQL engine of db/sql.h over libpq, used only by db/.
//
// Contract (beyond db/sql.h)
// - Every libpq failure becomes fsdb::Error(errc::kStorage, "<what> failed: <server message>"
//   [SQLSTATE]); a connection the server dropped is opened again by reconnect() (the store's pool
//   calls it before lending a broken connection), losing only its prepared statements.
// - Statements are prepared once per connection (PQprepare) and run with text parameters, except
//   blobs, which go as binary; results come as text (bytea as hex, decoded by columnBlob).
// - kWrite transactions take pg_advisory_xact_lock on the database's lock key (one per schema),
//   so writers from every server on the database run one at a time, as SQLite's do: the name,
//   cycle and version checks of a write cannot race, and the change log's sequence numbers
//   commit in order. kRead transactions are REPEATABLE READ READ ONLY: one snapshot.
// - The schema version is the one row of fsdb_schema (created by PostgresConnection::prepareSchema).
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "db/sql.h"

struct pg_conn;
struct pg_result;

namespace fsdb::postgres {

// A database address as fsdb takes it: a libpq URL (postgresql:// or postgres://) with one more
// optional query parameter, schema=NAME, which fsdb strips, creates when missing and puts first on
// the search_path: several catalogues can share one database.
struct Address {
  std::string conninfo;  // the URL for libpq, without schema=
  std::string schema;    // "" for the server's default (public)
  std::string display;   // the URL with any password replaced by ***, for logs and errors
};
// Throws kStorage for a malformed URL or schema name (letters, digits, _; not starting with a digit).
Address parseAddress(const std::string& url);
// true for postgresql:// and postgres:// URLs.
bool isPostgresUrl(const std::string& text);
// A URL for logs and errors: scheme://user:secret@host becomes scheme://user:***@host.
std::string hidePassword(const std::string& url);

class Statement final : public sql::Statement {
 public:
  Statement(pg_conn* connection, std::string name, std::string sql, int parameterCount);
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
  void set(int index, std::string value, bool binary);
  pg_conn* connection_;
  std::string name_, sql_;
  std::vector<std::string> values_;
  std::vector<char> isSet_, isBinary_;
  pg_result* result_ = nullptr;
  int row_ = -1, rows_ = 0;
};

class Connection final : public sql::Connection {
 public:
  // Connects and sets the session up (search_path to the address's schema, quiet notices).
  explicit Connection(const Address& address);
  ~Connection() override;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  sql::Dialect dialect() const override { return sql::Dialect::kPostgres; }
  void exec(const std::string& sql) override;
  sql::StatementRef prepare(const std::string& sql) override;
  bool inTransaction() const override;
  void begin(sql::TransactionMode mode) override;
  void rollbackQuietly() override;
  int schemaVersion() override;
  void setSchemaVersion(int version) override;

  // Creates the address's schema and the fsdb_schema table when missing, under the lock key (two
  // servers starting on a new database do not race).
  void prepareSchema();
  // true when the server closed the connection (restart, network): reconnect() before use, with no
  // statement on loan (reconnect drops the prepared statements).
  bool broken() const;
  void reconnect();

 private:
  void open();
  Address address_;
  int64_t lockKey_ = 0;  // of the schema: writers of other schemas do not wait for these
  pg_conn* connection_ = nullptr;
  std::unordered_map<std::string, std::unique_ptr<Statement>> statements_;
};

// "?1 ... ?12" -> "$1 ... $12" outside quotes; sets `parameterCount` to the highest number.
std::string numberedParameters(const std::string& sql, int& parameterCount);

}  // namespace fsdb::postgres
