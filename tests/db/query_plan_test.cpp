// The plans SQLite picks for the store's hot reads, checked with EXPLAIN QUERY PLAN on a migrated
// database without statistics (no ANALYZE has run: a fresh import's state). A plan that walks an
// index of every object of a kind makes a search at 1M parts a hundred times slower while every
// answer stays right, which no other test would notice.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "db/descriptor_index.h"
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

std::string planText(sqlite::Connection& db, const std::string& sql) {
  std::string all;
  for (const std::string& line : planOf(db, sql)) all += line + "\n";
  return all;
}

// The level scan's reads of a range: by value, the overlap index gives the order (no sorter,
// which would read the whole range to return a page of it); in id order, the primary key walks
// descriptor_index_walk gives one entry an id of the class (the overlap index would read the whole
// range, then sort it; the primary key would read each object's every descriptor row).
TEST(QueryPlan, DescriptorRangeReadsUseTheIndexThatGivesTheirOrder) {
  TempDir dir;
  Store::open(dir.file("plan.sqlite"));  // migrated
  sqlite::Connection db(dir.file("plan.sqlite"));
  using Order = DescriptorRangeRead::Order;
  for (const DescriptorRangeRead& read :
       {DescriptorRangeRead{Order::kAscending}, DescriptorRangeRead{Order::kAscending, 64},
        DescriptorRangeRead{Order::kDescending, 64}}) {
    const std::string plan = planText(db, descriptorRangeSql(read));
    EXPECT_NE(plan.find("USING COVERING INDEX descriptor_index_overlap"), std::string::npos) << plan;
    EXPECT_EQ(plan.find("TEMP B-TREE"), std::string::npos) << plan;
  }
  const std::string walk = planText(db, descriptorRangeSql({Order::kById, 0, 0, 100}));
  EXPECT_NE(walk.find("USING COVERING INDEX descriptor_index_walk (kind=? AND descriptor=? AND width_class=? AND "
                      "object_id>? AND object_id<?)"),
            std::string::npos)
      << walk;
  EXPECT_EQ(walk.find("descriptor_index_overlap"), std::string::npos) << walk;
  EXPECT_EQ(walk.find("TEMP B-TREE"), std::string::npos) << walk;
}

// The placeholder lists the store's statements are built from.
TEST(SqlText, PlaceholderLists) {
  EXPECT_EQ(sql::rowPlaceholders(2, 2), "(?1, ?2), (?3, ?4)");
  EXPECT_EQ(sql::listPlaceholders(2, 3), "?2, ?3, ?4");
  EXPECT_EQ(sql::listPlaceholders(1, 1), "?1");
  EXPECT_EQ(sql::listPlaceholders(5, 0), "");
}

}  // namespace
}  // namespace fsdb
