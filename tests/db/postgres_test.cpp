// db/postgres.h: the PostgreSQL connection of the store, on the test cluster
// ($FSDB_TEST_POSTGRES_URL; tests/db/test_database.h), and the URL and parameter rewriting
// without one.
#include "db/postgres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

#include "geometry/core/error.h"
#include "tests/db/expect_error.h"
#include "tests/db/test_database.h"

namespace fsdb::postgres {
namespace {

TEST(PostgresAddress, StripsTheSchemaAndHidesThePassword) {
  Address a = parseAddress("postgresql://alice:secret@db.example:5433/fsdb?sslmode=disable&schema=team_a");
  EXPECT_EQ(a.conninfo, "postgresql://alice:secret@db.example:5433/fsdb?sslmode=disable");
  EXPECT_EQ(a.schema, "team_a");
  EXPECT_EQ(a.display, "postgresql://alice:***@db.example:5433/fsdb?sslmode=disable&schema=team_a");
  Address b = parseAddress("postgres://bob@localhost/fsdb");
  EXPECT_EQ(b.conninfo, "postgres://bob@localhost/fsdb");
  EXPECT_EQ(b.schema, "");
  EXPECT_EQ(b.display, "postgres://bob@localhost/fsdb");
  EXPECT_TRUE(isPostgresUrl("postgres://x"));
  EXPECT_FALSE(isPostgresUrl("data/fsdb.sqlite"));
  for (const char* bad : {"postgresql://h/db?schema=", "postgresql://h/db?schema=a-b", "postgresql://h/db?schema=9x",
                          "postgresql://h/db?schema=a%22b"})
    expectError([&] { parseAddress(bad); }, errc::kStorage);
  expectError([&] { parseAddress("mysql://h/db"); }, errc::kStorage);
}

TEST(PostgresParameters, QuestionNumbersBecomeDollarNumbersOutsideQuotes) {
  int count = 0;
  EXPECT_EQ(numberedParameters("SELECT ?1, '?2', \"?3\" WHERE a = ?12 AND b = ?2", count),
            "SELECT $1, '?2', \"?3\" WHERE a = $12 AND b = $2");
  EXPECT_EQ(count, 12);
  EXPECT_EQ(numberedParameters("SELECT 1", count), "SELECT 1");
  EXPECT_EQ(count, 0);
}

class PostgresConnectionTest : public testing::Test {
 protected:
  void SetUp() override {
    FSDB_USE_BACKEND("postgresql");
    db = std::make_unique<Connection>(parseAddress(database.location()));
    db->prepareSchema();
  }
  test::TestDatabase database{"postgresql"};
  std::unique_ptr<Connection> db;
};

TEST_F(PostgresConnectionTest, ValuesRoundTripExactly) {
  db->exec("CREATE TABLE t (i BIGINT, d DOUBLE PRECISION, s TEXT, b BYTEA)");
  const double tiny = std::nextafter(0.3, 1.0), inf = std::numeric_limits<double>::infinity();
  std::string blob("\0\x01\xff\\x", 5);
  auto insert = db->prepare("INSERT INTO t VALUES (?1, ?2, ?3, ?4)");
  insert->bind(1, int64_t{9007199254740993}).bind(2, tiny).bind(3, "it's \"quoted\" ?1").bindBlob(4, blob);
  insert->run();
  insert->reset();
  insert->bind(1, int64_t{-1}).bind(2, -inf).bindNull(3).bindBlob(4, "");
  insert->run();
  auto select = db->prepare("SELECT i, d, s, b FROM t ORDER BY i DESC");
  ASSERT_TRUE(select->step());
  EXPECT_EQ(select->columnInt(0), 9007199254740993);
  EXPECT_EQ(select->columnDouble(1), tiny);  // bit for bit
  EXPECT_EQ(select->columnText(2), "it's \"quoted\" ?1");
  EXPECT_EQ(select->columnBlob(3), blob);
  ASSERT_TRUE(select->step());
  EXPECT_EQ(select->columnDouble(1), -inf);
  EXPECT_TRUE(select->isNull(2));
  EXPECT_EQ(select->columnOptionalInt(2), std::nullopt);
  EXPECT_EQ(select->columnBlob(3), "");
  EXPECT_FALSE(select->step());
}

TEST_F(PostgresConnectionTest, ErrorsAreStorageErrorsWithTheServersMessage) {
  auto message = expectError([&] { db->prepare("SELEC nonsense"); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "syntax error");
  db->exec("CREATE TABLE u (x INTEGER UNIQUE)");
  db->exec("INSERT INTO u VALUES (1)");
  auto insert = db->prepare("INSERT INTO u VALUES (?1)");
  insert->bind(1, 1);
  message = expectError([&] { insert->run(); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "SQLSTATE 23505");
  expectError([&] { db->prepare("SELECT ?1::int")->bind(3, 1); }, errc::kStorage);
}

TEST_F(PostgresConnectionTest, SavepointRollbackClearsAFailedStatement) {
  db->exec("CREATE TABLE u (x INTEGER UNIQUE)");
  sql::Transaction transaction(*db);
  db->exec("INSERT INTO u VALUES (1)");
  {
    sql::Savepoint savepoint(*db, "item");
    expectError([&] { db->exec("INSERT INTO u VALUES (1)"); }, errc::kStorage);
  }  // rolled back to the savepoint: the transaction goes on
  db->exec("INSERT INTO u VALUES (2)");
  transaction.commit();
  auto count = db->prepare("SELECT COUNT(*) FROM u");
  ASSERT_TRUE(count->step());
  EXPECT_EQ(count->columnInt(0), 2);
}

TEST_F(PostgresConnectionTest, WriteTransactionsOfTwoConnectionsRunOneAtATime) {
  Connection other(parseAddress(database.location()));
  db->exec("CREATE TABLE log (who TEXT, at TIMESTAMPTZ DEFAULT clock_timestamp())");
  sql::Transaction first(*db);
  std::thread second([&] {
    sql::Transaction transaction(other);  // waits for `first` to commit
    other.exec("INSERT INTO log (who) VALUES ('second')");
    transaction.commit();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  db->exec("INSERT INTO log (who) VALUES ('first')");
  first.commit();
  second.join();
  auto order = db->prepare("SELECT who FROM log ORDER BY at");
  ASSERT_TRUE(order->step());
  EXPECT_EQ(order->columnText(0), "first");
}

TEST_F(PostgresConnectionTest, ReconnectAfterTheServerDropsTheConnection) {
  Connection killer(parseAddress(database.location()));
  int64_t backend = 0;
  {  // statements are borrowed only for a call: reconnect() drops the prepared ones
    auto pid = db->prepare("SELECT pg_backend_pid()");
    ASSERT_TRUE(pid->step());
    backend = pid->columnInt(0);
  }
  {
    auto kill = killer.prepare("SELECT pg_terminate_backend(CAST(?1 AS INTEGER))");
    kill->bind(1, backend);
    kill->run();
  }
  expectError([&] { db->exec("SELECT 1"); }, errc::kStorage);
  EXPECT_TRUE(db->broken());
  db->reconnect();
  EXPECT_FALSE(db->broken());
  auto again = db->prepare("SELECT 41 + 1");
  ASSERT_TRUE(again->step());
  EXPECT_EQ(again->columnInt(0), 42);
}

}  // namespace
}  // namespace fsdb::postgres
