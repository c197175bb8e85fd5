// db/sqlite.h: connections, statements (bind/step/columns/reset, the cache), transactions,
// savepoints, and the one error shape: storage_error "<what> failed: <sqlite message>".
#include "db/sqlite.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "geometry/core/error.h"
#include "tests/db/expect_error.h"
#include "tests/db/temp_dir.h"

namespace fsdb::sqlite {
namespace {

// f() fails with storage_error and a message containing `fragment`.
template <class F>
void expectStorageError(F f, const std::string& fragment) {
  FSDB_EXPECT_CONTAINS(expectError(f, errc::kStorage), fragment);
}

class SqliteTest : public testing::Test {
 protected:
  TempDir dir;
  Connection db{dir.file("test.db")};
  int64_t count(const std::string& table) {
    auto statement = db.prepare("SELECT COUNT(*) FROM " + table);
    EXPECT_TRUE(statement->step());
    return statement->columnInt(0);
  }
};

TEST_F(SqliteTest, OpensInWalWithForeignKeys) {
  auto mode = db.prepare("PRAGMA journal_mode");
  ASSERT_TRUE(mode->step());
  EXPECT_EQ(mode->columnText(0), "wal");
  auto keys = db.prepare("PRAGMA foreign_keys");
  ASSERT_TRUE(keys->step());
  EXPECT_EQ(keys->columnInt(0), 1);
  auto sync = db.prepare("PRAGMA synchronous");
  ASSERT_TRUE(sync->step());
  EXPECT_EQ(sync->columnInt(0), 1);  // NORMAL
}

TEST_F(SqliteTest, SynchronousFullOption) {
  Connection full(dir.file("full.db"), ConnectionOptions{1000, true});
  auto sync = full.prepare("PRAGMA synchronous");
  ASSERT_TRUE(sync->step());
  EXPECT_EQ(sync->columnInt(0), 2);  // FULL
}

TEST_F(SqliteTest, OpenFailureNamesThePath) {
  std::string bad = dir.file("missing_dir/x.db");
  expectStorageError([&] { Connection c(bad); }, bad);
}

TEST_F(SqliteTest, BindsAndReadsEveryType) {
  db.exec("CREATE TABLE t (i INTEGER, d REAL, s TEXT, b BLOB, n INTEGER)");
  auto insert = db.prepare("INSERT INTO t VALUES (?1, ?2, ?3, ?4, ?5)");
  std::string blob("a\0b", 3);
  insert->bind(1, int64_t{1} << 40).bind(2, 2.5).bind(3, "it's").bindBlob(4, blob).bindNull(5);
  insert->run();
  EXPECT_EQ(db.changes(), 1);
  EXPECT_EQ(db.lastInsertId(), 1);
  auto select = db.prepare("SELECT i, d, s, b, n FROM t");
  ASSERT_TRUE(select->step());
  EXPECT_EQ(select->columnInt(0), int64_t{1} << 40);
  EXPECT_DOUBLE_EQ(select->columnDouble(1), 2.5);
  EXPECT_EQ(select->columnText(2), "it's");
  EXPECT_EQ(select->columnBlob(3), blob);
  EXPECT_TRUE(select->isNull(4));
  EXPECT_FALSE(select->isNull(0));
  EXPECT_EQ(select->columnOptionalInt(4), std::nullopt);
  EXPECT_EQ(select->columnOptionalInt(0), int64_t{1} << 40);
  EXPECT_EQ(select->columnText(4), "");
  EXPECT_FALSE(select->step());
}

TEST_F(SqliteTest, OptionalBindsNull) {
  auto statement = db.prepare("SELECT ?1 IS NULL, ?2");
  statement->bind(1, std::optional<int64_t>()).bind(2, std::optional<int64_t>(7));
  ASSERT_TRUE(statement->step());
  EXPECT_EQ(statement->columnInt(0), 1);
  EXPECT_EQ(statement->columnInt(1), 7);
}

TEST_F(SqliteTest, CachedStatementIsResetAfterEachUse) {
  db.exec("CREATE TABLE t (x INTEGER)");
  db.exec("INSERT INTO t VALUES (1), (2)");
  const std::string sql = "SELECT x FROM t ORDER BY x";
  sql::Statement* first = nullptr;
  {
    auto statement = db.prepare(sql);
    first = &*statement;
    ASSERT_TRUE(statement->step());  // left mid-result on purpose
  }
  auto again = db.prepare(sql);
  EXPECT_EQ(&*again, first);  // the same prepared statement
  ASSERT_TRUE(again->step());
  EXPECT_EQ(again->columnInt(0), 1);  // from the first row: it was reset
}

TEST_F(SqliteTest, ResetClearsBindings) {
  auto statement = db.prepare("SELECT ?1");
  statement->bind(1, 5);
  statement->reset();
  ASSERT_TRUE(statement->step());
  EXPECT_TRUE(statement->isNull(0));
}

TEST_F(SqliteTest, ErrorsAreStorageErrorsWithSqliteMessage) {
  expectStorageError([&] { db.prepare("SELEC nonsense"); }, "syntax error");
  expectStorageError([&] { db.exec("DROP TABLE nowhere"); }, "no such table");
  db.exec("CREATE TABLE u (x INTEGER UNIQUE)");
  db.exec("INSERT INTO u VALUES (1)");
  auto insert = db.prepare("INSERT INTO u VALUES (?1)");
  insert->bind(1, 1);
  expectStorageError([&] { insert->run(); }, "UNIQUE constraint failed");
  expectStorageError([&] { db.prepare("SELECT ?1")->bind(3, 1); }, "bind of parameter 3");
}

TEST_F(SqliteTest, TransactionCommitsOrRollsBack) {
  db.exec("CREATE TABLE t (x INTEGER)");
  {
    Transaction transaction(db);
    EXPECT_TRUE(db.inTransaction());
    db.exec("INSERT INTO t VALUES (1)");
  }  // no commit: rolled back
  EXPECT_FALSE(db.inTransaction());
  EXPECT_EQ(count("t"), 0);
  {
    Transaction transaction(db, Transaction::Mode::kRead);
    db.exec("INSERT INTO t VALUES (1)");
    transaction.commit();
  }
  EXPECT_EQ(count("t"), 1);
}

TEST_F(SqliteTest, ImmediateTransactionTakesTheWriteLock) {
  Connection other(dir.file("test.db"), ConnectionOptions{50, false});
  Transaction transaction(db);
  // The second writer waits busyTimeoutMs, then fails as a storage error, never half-written.
  expectStorageError([&] { Transaction second(other); }, "locked");
}

TEST_F(SqliteTest, SavepointRollsBackOnlyItsPart) {
  db.exec("CREATE TABLE t (x INTEGER)");
  Transaction transaction(db);
  db.exec("INSERT INTO t VALUES (1)");
  {
    Savepoint kept(db, "kept");
    db.exec("INSERT INTO t VALUES (2)");
    kept.release();
  }
  {
    Savepoint dropped(db, "dropped");
    db.exec("INSERT INTO t VALUES (3)");
  }  // destroyed without release
  {
    Savepoint undone(db, "undone");
    db.exec("INSERT INTO t VALUES (4)");
    undone.rollback();
  }
  EXPECT_TRUE(db.inTransaction());
  transaction.commit();
  EXPECT_EQ(count("t"), 2);
  auto sum = db.prepare("SELECT SUM(x) FROM t");
  ASSERT_TRUE(sum->step());
  EXPECT_EQ(sum->columnInt(0), 3);
}

// Checkpoint starvation: with SQLite's automatic PASSIVE checkpoint alone, a WAL under reads that
// never pause (two readers taking turns, one snapshot always open) grew with every commit, 250
// MiB here. The RESTART checkpoint (db/sqlite.h) keeps it near kWalRestartFrames pages.
TEST_F(SqliteTest, WalStaysBoundedUnderReadersThatNeverStop) {
  db.exec("CREATE TABLE t (id INTEGER PRIMARY KEY, b BLOB)");
  db.exec("INSERT INTO t (b) VALUES (zeroblob(100))");
  std::atomic<bool> writing{true};
  std::atomic<long> reads{0};
  std::thread readers([&] {
    Connection first(dir.file("test.db")), second(dir.file("test.db"));
    auto read = [&](Connection& c) {
      c.exec("BEGIN");
      auto row = c.prepare("SELECT length(b) FROM t WHERE id = 1");
      EXPECT_TRUE(row->step());
      ++reads;
    };
    read(first);
    while (writing) {  // one of the two always holds a snapshot
      read(second);
      first.exec("COMMIT");
      read(first);
      second.exec("COMMIT");
    }
    first.exec("COMMIT");
  });
  const int64_t written = int64_t{256} << 20;  // 256 MiB of pages through the WAL
  uintmax_t largest = 0;
  for (int64_t total = 0; total < written; total += 100000) {
    {
      Transaction transaction(db);
      db.prepare("INSERT INTO t (b) VALUES (zeroblob(?1))")->bind(1, int64_t{100000}).run();
      db.exec("DELETE FROM t WHERE id > 1");
      transaction.commit();
    }
    std::error_code missing;  // no WAL file yet: size 0
    const uintmax_t size = std::filesystem::file_size(dir.file("test.db") + "-wal", missing);
    if (!missing) largest = std::max(largest, size);
  }
  writing = false;
  readers.join();
  EXPECT_GT(reads.load(), 100);
  // Bounded by the RESTART threshold plus the commits made while readers of older snapshots
  // finished, and by journal_size_limit on the file; never the 256 MiB written.
  EXPECT_LE(largest, uintmax_t(kWalSizeLimitBytes)) << "WAL grew to " << largest / (1 << 20) << " MiB";
}

TEST_F(SqliteTest, FailThrowsStorageError) {
  expectStorageError([&] { fail(db.handle(), "custom step"); }, "custom step failed: ");
}

}  // namespace
}  // namespace fsdb::sqlite
