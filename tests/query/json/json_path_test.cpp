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

}  // namespace
}  // namespace fsdb
