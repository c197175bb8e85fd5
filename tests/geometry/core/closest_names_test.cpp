#include "geometry/core/closest_names.h"

#include <gtest/gtest.h>

namespace fsdb {
namespace {

TEST(ClosestNames, EditDistance) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("bent", "bent"), 0u);
  EXPECT_EQ(editDistance("bnet", "bent"), 2u);
  EXPECT_EQ(editDistance("cylindr", "cylinder"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(ClosestNames, NearestFirstTiesAlphabetical) {
  const std::vector<std::string> known = {"round", "bent", "best", "sphere", "bent"};
  EXPECT_EQ(closestNames("bnet", known), "bent, best, round");
  EXPECT_EQ(closestNames("bnet", known, 1), "bent");
  EXPECT_EQ(closestNames("x", {}), "");
}

}  // namespace
}  // namespace fsdb
