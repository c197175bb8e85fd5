// The plans SQLite picks for the store's hot reads, checked with EXPLAIN QUERY PLAN on a migrated
// database without statistics (no ANALYZE has run: a fresh import's state). A plan that walks an
// index of every object of a kind makes a search at 1M parts a hundred times slower while every
// answer stays right, which no other test would notice.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "db/object_rows.h"
#include "db/sqlite.h"
#include "db/store.h"
#include "tests/db/temp_dir.h"

namespace fsdb {
namespace {

std::vector<std::string> planOf(sqlite::Connection& db, const std::string& sql) {
  auto plan = db.prepare("EXPLAIN QUERY PLAN " + sql);
  std::vector<std::string> lines;
  while (plan->step()) lines.push_back(plan->columnText(3));
  return lines;
}

TEST(QueryPlan, IndexedObjectsLooksObjectsUpByPrimaryKey) {
  TempDir dir;
  Store::open(dir.file("plan.sqlite"));  // migrated
  sqlite::Connection db(dir.file("plan.sqlite"));
  const std::vector<std::string> plan = planOf(db, object_rows::indexedObjectsSql(sql::Dialect::kSqlite, 4));
  ASSERT_FALSE(plan.empty());
  std::string all;
  for (const std::string& line : plan) all += line + "\n";
  EXPECT_NE(plan[0].find("SEARCH o USING INTEGER PRIMARY KEY"), std::string::npos) << all;
  EXPECT_EQ(all.find("objects_kind_name"), std::string::npos) << all;
}

}  // namespace
}  // namespace fsdb
