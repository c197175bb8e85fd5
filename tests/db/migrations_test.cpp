// db/migrations.h: in-order application tracked by user_version, one transaction each, and the
// refusal of a database newer than the binary.
#include "db/migrations.h"

#include <gtest/gtest.h>

#include "db/sqlite.h"
#include "db/store.h"
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

// 009: the objects of an older database get their search words (name, a string description,
// the strings of their descriptors), as the store writes them for new versions.
TEST(ObjectTextMigration, ObjectsOfAnOlderDatabaseAreFoundByTheirWords) {
  TempDir dir;
  const std::string path = dir.file("old.db");
  {
    sqlite::Connection db(path);
    std::vector<std::pair<int, std::string>> upTo8;
    for (const auto& m : embeddedMigrations())
      if (m.first <= 8) upTo8.push_back(m);
    ASSERT_EQ(applyMigrations(db, upTo8), 8);
    db.exec("INSERT INTO objects (kind, name, latest_version) VALUES ('part', 'desk-lamp', 2), ('shape', 'pair', 1),"
            " ('curve', 'arc', 1)");
    db.exec("INSERT INTO versions VALUES"
            " (1, 1, '{\"meta\":{\"description\":\"an old torch\"}}', 'h', '2026-01-01T00:00:00.000Z'),"
            " (1, 2, '{\"meta\":{\"description\":\"a reading light\"},\"descriptors\":[\"slightly bent\",3]}', 'h',"
            " '2026-01-01T00:00:00.000Z'),"
            " (2, 1, '{\"meta\":{\"description\":7}}', 'h', '2026-01-01T00:00:00.000Z'),"
            " (3, 1, '{\"meta\":{\"description\":\"a reading arc\"}}', 'h', '2026-01-01T00:00:00.000Z')");
  }
  auto store = Store::open(path);
  const auto ids = [&](const std::vector<std::string>& words) {
    std::vector<int64_t> out;
    for (const StoredObject& o : store->described(words, {"part", "shape"}, 10)) out.push_back(o.id);
    return out;
  };
  EXPECT_EQ(ids({"reading", "light", "bent"}), std::vector<int64_t>{1});  // the latest version's
  EXPECT_TRUE(ids({"torch"}).empty());
  EXPECT_EQ(ids({"lamp"}), std::vector<int64_t>{1});  // the name's words
  EXPECT_EQ(ids({"pair"}), std::vector<int64_t>{2});  // a description that is no string is left out
  EXPECT_TRUE(ids({"arc"}).empty());                  // curves are not searched by words
}

}  // namespace
}  // namespace fsdb
