// See db/postgres.h.
#include "db/postgres.h"

#include <libpq-fe.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geometry/core/error.h"

namespace fsdb::postgres {

namespace {

[[noreturn]] void fail(pg_conn* connection, const std::string& what, pg_result* result = nullptr) {
  std::string message = result ? PQresultErrorMessage(result) : "";
  if (message.empty() && connection) message = PQerrorMessage(connection);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  const char* state = result ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  if (state) message += std::string(" [SQLSTATE ") + state + "]";
  if (result) PQclear(result);
  throw Error(errc::kStorage, what + " failed: " + message);
}

bool ok(pg_result* result) {
  const ExecStatusType status = PQresultStatus(result);
  return status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK;
}

// Notices (CREATE ... IF NOT EXISTS "already exists, skipping") are not errors; fsdb does not log them.
void quiet(void*, const char*) {}

bool validSchemaName(const std::string& name) {
  if (name.empty() || name.size() > 63 || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// FNV-1a of the schema name, folded to 31 bits: the second key of pg_advisory_xact_lock(int, int).
int64_t lockKeyOf(const std::string& schema) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : schema) h = (h ^ c) * 1099511628211ull;
  return static_cast<int64_t>(h & 0x7fffffff);
}

// The first key: 'fsdb' in ASCII, so fsdb's locks are told apart from other programs' on the database.
constexpr int64_t kLockClass = 0x66736462;

}  // namespace

bool isPostgresUrl(const std::string& text) {
  return text.rfind("postgresql://", 0) == 0 || text.rfind("postgres://", 0) == 0;
}

Address parseAddress(const std::string& url) {
  if (!isPostgresUrl(url))
    throw Error(errc::kStorage, "'" + url + "' is not a PostgreSQL URL (postgresql://user@host:port/database)");
  Address address;
  const size_t question = url.find('?');
  std::string base = url.substr(0, question), kept;
  if (question != std::string::npos) {
    std::string query = url.substr(question + 1);
    size_t start = 0;
    while (start <= query.size()) {
      size_t end = query.find('&', start);
      if (end == std::string::npos) end = query.size();
      const std::string parameter = query.substr(start, end - start);
      if (parameter.rfind("schema=", 0) == 0) {
        address.schema = parameter.substr(7);
        if (!validSchemaName(address.schema))
          throw Error(errc::kStorage, "schema '" + address.schema +
                                          "' in the database URL: a schema name is letters, digits and _, "
                                          "not starting with a digit, at most 63 characters");
      } else if (!parameter.empty()) {
        kept += (kept.empty() ? "" : "&") + parameter;
      }
      start = end + 1;
    }
  }
  address.conninfo = kept.empty() ? base : base + "?" + kept;
  address.display = hidePassword(url);
  return address;
}

std::string hidePassword(const std::string& url) {
  // scheme://user:secret@host -> scheme://user:***@host
  const size_t slashes = url.find("://");
  if (slashes == std::string::npos) return url;
  const size_t scheme = slashes + 3, at = url.find('@', scheme);
  if (at == std::string::npos) return url;
  const size_t colon = url.find(':', scheme);
  return colon != std::string::npos && colon < at ? url.substr(0, colon + 1) + "***" + url.substr(at) : url;
}

std::string numberedParameters(const std::string& sql, int& parameterCount) {
  std::string out;
  out.reserve(sql.size());
  parameterCount = 0;
  char quote = 0;
  for (size_t i = 0; i < sql.size(); ++i) {
    const char c = sql[i];
    if (quote) {
      if (c == quote) quote = 0;
      out += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      out += c;
    } else if (c == '?' && i + 1 < sql.size() && std::isdigit(static_cast<unsigned char>(sql[i + 1]))) {
      size_t j = i + 1;
      int number = 0;
      while (j < sql.size() && std::isdigit(static_cast<unsigned char>(sql[j])))
        number = number * 10 + (sql[j++] - '0');
      parameterCount = std::max(parameterCount, number);
      out += '$';
      out += sql.substr(i + 1, j - i - 1);
      i = j - 1;
    } else {
      out += c;
    }
  }
  return out;
}

// --- Statement ---------------------------------------------------------------------------------

Statement::Statement(pg_conn* connection, std::string name, std::string sql, int parameterCount)
    : connection_(connection), name_(std::move(name)), sql_(std::move(sql)) {
  values_.resize(parameterCount);
  isSet_.assign(parameterCount, 0);
  isBinary_.assign(parameterCount, 0);
}

Statement::~Statement() {
  if (result_) PQclear(result_);
}

void Statement::set(int index, std::string value, bool binary) {
  if (index < 1 || index > static_cast<int>(values_.size()))
    throw Error(errc::kStorage, "bind of parameter " + std::to_string(index) + " failed: '" + sql_ + "' has " +
                                    std::to_string(values_.size()));
  values_[index - 1] = std::move(value);
  isSet_[index - 1] = 1;
  isBinary_[index - 1] = binary ? 1 : 0;
}

sql::Statement& Statement::bind(int index, int64_t value) {
  set(index, std::to_string(value), false);
  return *this;
}

sql::Statement& Statement::bind(int index, double value) {
  char text[40];
  if (std::isnan(value)) std::snprintf(text, sizeof text, "NaN");
  else if (std::isinf(value)) std::snprintf(text, sizeof text, value > 0 ? "Infinity" : "-Infinity");
  else std::snprintf(text, sizeof text, "%.17g", value);  // round-trips every double
  set(index, text, false);
  return *this;
}

sql::Statement& Statement::bind(int index, const std::string& text) {
  set(index, text, false);
  return *this;
}

sql::Statement& Statement::bindBlob(int index, const std::string& bytes) {
  set(index, bytes, true);
  return *this;
}

sql::Statement& Statement::bindNull(int index) {
  set(index, "", false);
  isSet_[index - 1] = 0;
  return *this;
}

bool Statement::step() {
  if (!result_) {
    const int n = static_cast<int>(values_.size());
    std::vector<const char*> values(n);
    std::vector<int> lengths(n), formats(n);
    for (int i = 0; i < n; ++i) {
      values[i] = isSet_[i] ? values_[i].data() : nullptr;
      lengths[i] = static_cast<int>(values_[i].size());
      formats[i] = isBinary_[i];
    }
    result_ = PQexecPrepared(connection_, name_.c_str(), n, values.data(), lengths.data(), formats.data(), 0);
    if (!ok(result_)) {
      pg_result* failed = result_;
      result_ = nullptr;
      fail(connection_, "'" + sql_ + "'", failed);
    }
    rows_ = PQntuples(result_);
    row_ = -1;
  }
  return ++row_ < rows_;
}

void Statement::reset() {
  if (result_) PQclear(result_);
  result_ = nullptr;
  row_ = -1;
  rows_ = 0;
  for (size_t i = 0; i < values_.size(); ++i) {
    values_[i].clear();
    isSet_[i] = 0;
    isBinary_[i] = 0;
  }
}

bool Statement::isNull(int column) const { return PQgetisnull(result_, row_, column) != 0; }

int64_t Statement::columnInt(int column) const {
  if (isNull(column)) return 0;
  return std::strtoll(PQgetvalue(result_, row_, column), nullptr, 10);
}

double Statement::columnDouble(int column) const {
  if (isNull(column)) return 0;
  return std::strtod(PQgetvalue(result_, row_, column), nullptr);  // also reads Infinity, -Infinity, NaN
}

std::string Statement::columnText(int column) const {
  if (isNull(column)) return "";
  return std::string(PQgetvalue(result_, row_, column), static_cast<size_t>(PQgetlength(result_, row_, column)));
}

std::string Statement::columnBlob(int column) const {
  if (isNull(column)) return "";
  size_t size = 0;
  unsigned char* bytes =
      PQunescapeBytea(reinterpret_cast<const unsigned char*>(PQgetvalue(result_, row_, column)), &size);
  if (!bytes) throw Error(errc::kStorage, "decoding a bytea column of '" + sql_ + "' failed: out of memory");
  std::string out(reinterpret_cast<const char*>(bytes), size);
  PQfreemem(bytes);
  return out;
}

// --- Connection --------------------------------------------------------------------------------

Connection::Connection(const Address& address) : address_(address), lockKey_(lockKeyOf(address.schema)) { open(); }

Connection::~Connection() {
  statements_.clear();
  if (connection_) PQfinish(connection_);
}

void Connection::open() {
  connection_ = PQconnectdb(address_.conninfo.c_str());
  if (PQstatus(connection_) != CONNECTION_OK) {
    std::string message = PQerrorMessage(connection_);
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    PQfinish(connection_);
    connection_ = nullptr;
    throw Error(errc::kStorage, "cannot connect to " + address_.display + ": " + message);
  }
  PQsetNoticeProcessor(connection_, quiet, nullptr);
  // Text comparisons and ORDER BY as in SQLite (bytewise), whatever the database's locale; the
  // columns are COLLATE "C" as well (schema/migrations/postgresql/001_init.sql).
  exec("SET client_min_messages = warning");
  if (!address_.schema.empty()) exec("SET search_path TO \"" + address_.schema + "\"");
}

bool Connection::broken() const { return !connection_ || PQstatus(connection_) != CONNECTION_OK; }

void Connection::reconnect() {
  statements_.clear();
  if (connection_) PQfinish(connection_);
  connection_ = nullptr;
  open();
}

void Connection::exec(const std::string& sql) {
  pg_result* result = PQexec(connection_, sql.c_str());
  if (!ok(result)) fail(connection_, "'" + sql.substr(0, 80) + "'", result);
  PQclear(result);
}

sql::StatementRef Connection::prepare(const std::string& sql) {
  auto found = statements_.find(sql);
  if (found == statements_.end()) {
    int parameters = 0;
    const std::string text = numberedParameters(sql, parameters);
    const std::string name = "fsdb_" + std::to_string(statements_.size());
    pg_result* result = PQprepare(connection_, name.c_str(), text.c_str(), 0, nullptr);
    if (!ok(result)) fail(connection_, "prepare of '" + sql + "'", result);
    PQclear(result);
    found = statements_.emplace(sql, std::make_unique<Statement>(connection_, name, sql, parameters)).first;
  }
  return sql::StatementRef(*found->second);
}

bool Connection::inTransaction() const {
  const PGTransactionStatusType status = PQtransactionStatus(connection_);
  return status == PQTRANS_INTRANS || status == PQTRANS_INERROR || status == PQTRANS_ACTIVE;
}

void Connection::begin(sql::TransactionMode mode) {
  if (mode == sql::TransactionMode::kRead) {
    exec("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY");
    return;
  }
  exec("BEGIN");
  try {
    // Our own integers, not input.
    exec("SELECT pg_advisory_xact_lock(" + std::to_string(kLockClass) + ", " + std::to_string(lockKey_) + ")");
  } catch (...) {
    rollbackQuietly();
    throw;
  }
}

void Connection::rollbackQuietly() {
  if (broken()) return;
  PQclear(PQexec(connection_, "ROLLBACK"));
}

void Connection::prepareSchema() {
  sql::Transaction transaction(*this);
  if (!address_.schema.empty()) exec("CREATE SCHEMA IF NOT EXISTS \"" + address_.schema + "\"");
  exec("CREATE TABLE IF NOT EXISTS fsdb_schema (one INTEGER PRIMARY KEY CHECK (one = 1), version INTEGER NOT NULL)");
  exec("INSERT INTO fsdb_schema (one, version) VALUES (1, 0) ON CONFLICT (one) DO NOTHING");
  transaction.commit();
}

int Connection::schemaVersion() {
  auto statement = prepare("SELECT version FROM fsdb_schema");
  return statement->step() ? static_cast<int>(statement->columnInt(0)) : 0;
}

void Connection::setSchemaVersion(int version) {
  auto statement = prepare("UPDATE fsdb_schema SET version = ?1");
  statement->bind(1, version);
  statement->run();
}

}  // namespace fsdb::postgres
