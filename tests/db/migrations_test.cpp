// db/migrations.h: in-order application tracked by user_version, one transaction each, and the
// refusal of a database newer than the binary.
#include "db/migrations.h"

#include <gtest/gtest.h>

#include "db/sqlite.h"
#include "geometry/core/error.h"
#include "tests/db/expect_error.h"
#include "tests/db/temp_dir.h"

namespace fsdb {
namespace {

bool hasTable(sqlite::Connection& db, const std::string& name) {
  auto statement = db.prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?1");
  statement->bind(1, name);
  return statement->step();
}

class MigrationsTest : public testing::Test {
 protected:
  TempDir dir;
  sqlite::Connection db{dir.file("m.db")};
};

TEST(EmbeddedMigrations, StartWithInitAtVersionOne) {
  const auto& migrations = embeddedMigrations();
  ASSERT_FALSE(migrations.empty());
  EXPECT_EQ(migrations.front().first, 1);
  EXPECT_NE(migrations.front().second.find("CREATE TABLE objects"), std::string::npos);
  for (size_t i = 1; i < migrations.size(); ++i) EXPECT_LT(migrations[i - 1].first, migrations[i].first);
}

TEST_F(MigrationsTest, AppliesEmbeddedSchema) {
  EXPECT_EQ(schemaVersionOf(db), 0);
  EXPECT_EQ(applyMigrations(db, embeddedMigrations()), embeddedMigrations().back().first);
  for (const char* table : {"objects", "versions", "refs", "csg_nodes", "eval_cache", "descriptor_index", "change_log"})
    EXPECT_TRUE(hasTable(db, table)) << table;
  EXPECT_FALSE(hasTable(db, "part_parameters"));  // 005: written by every part, read by nothing
  // Idempotent: a second run applies nothing and fails on nothing.
  EXPECT_EQ(applyMigrations(db, embeddedMigrations()), embeddedMigrations().back().first);
}

TEST_F(MigrationsTest, AppliesInVersionOrderAndOnlyNewOnes) {
  // Given out of order: 2 needs 1's table.
  std::vector<std::pair<int, std::string>> migrations = {{2, "INSERT INTO log VALUES ('two')"},
                                                         {1, "CREATE TABLE log (what TEXT)"}};
  EXPECT_EQ(applyMigrations(db, migrations), 2);
  migrations.push_back({3, "INSERT INTO log VALUES ('three')"});
  EXPECT_EQ(applyMigrations(db, migrations), 3);
  auto statement = db.prepare("SELECT group_concat(what, ',') FROM log");
  ASSERT_TRUE(statement->step());
  EXPECT_EQ(statement->columnText(0), "two,three");  // 1 and 2 not applied twice
}

TEST_F(MigrationsTest, FailedMigrationLeavesPreviousVersion) {
  std::vector<std::pair<int, std::string>> migrations = {{1, "CREATE TABLE a (x)"},
                                                         {2, "CREATE TABLE b (x); INSERT INTO nowhere VALUES (1)"}};
  FSDB_EXPECT_CONTAINS(expectError([&] { applyMigrations(db, migrations); }, errc::kStorage), "migration 2");
  EXPECT_EQ(schemaVersionOf(db), 1);
  EXPECT_TRUE(hasTable(db, "a"));
  EXPECT_FALSE(hasTable(db, "b"));  // rolled back with its transaction
}

TEST_F(MigrationsTest, RefusesNewerDatabase) {
  db.exec("PRAGMA user_version = 99");
  auto message = expectError([&] { applyMigrations(db, embeddedMigrations()); }, errc::kStorage);
  FSDB_EXPECT_CONTAINS(message, "99");
  FSDB_EXPECT_CONTAINS(message, "newer");
  EXPECT_FALSE(hasTable(db, "objects"));
}

}  // namespace
}  // namespace fsdb
