#include "query/json/json_path.h"

#include <gtest/gtest.h>

namespace fsdb {
namespace {

TEST(JsonPath, JoinsKeysAndIndices) {
  EXPECT_EQ(joinPath("", "params"), "params");
  EXPECT_EQ(joinPath("params", "eps2"), "params.eps2");
  EXPECT_EQ(joinPath(joinPath("params.eps2", "tri"), 1), "params.eps2.tri[1]");
  EXPECT_EQ(joinPath("", 3), "[3]");
  EXPECT_EQ(joinPath(joinPath("points", 2), 0), "points[2][0]");
}

// The events of {"params": {"eps2": {"tri": [0.1, 1e999 ...: the path names the value being read.
TEST(JsonPathTracker, NamesTheValueBeingRead) {
  JsonPathTracker t;
  EXPECT_EQ(t.path(), "");
  EXPECT_EQ(t.depth(), 0u);
  t.openObject();
  t.key("params");
  EXPECT_EQ(t.path(), "params");
  t.openObject();
  t.key("eps2");
  t.openObject();
  t.key("tri");
  t.openArray();
  EXPECT_EQ(t.path(), "params.eps2.tri[0]");
  t.valueDone();
  EXPECT_EQ(t.path(), "params.eps2.tri[1]");
  EXPECT_EQ(t.depth(), 4u);
  // A closed container is one value of the array around it.
  JsonPathTracker list;
  list.openArray();
  list.openObject();
  list.key("name");
  list.valueDone();  // inside an object: no index moves
  EXPECT_EQ(list.path(), "[0].name");
  list.close();
  EXPECT_EQ(list.path(), "[1]");
  list.close();
  EXPECT_EQ(list.depth(), 0u);
  list.close();  // unbalanced closes are ignored
  EXPECT_EQ(list.path(), "");
}

}  // namespace
}  // namespace fsdb
