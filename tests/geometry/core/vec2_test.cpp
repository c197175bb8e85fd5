#include "geometry/core/vec2.h"

#include <gtest/gtest.h>

namespace fsdb {
namespace {

TEST(Vec2, Arithmetic) {
  const Vec2 a{1, 2}, b{3, -1};
  EXPECT_EQ((a + b).x, 4.0);
  EXPECT_EQ((a - b).y, 3.0);
  EXPECT_EQ((-a).x, -1.0);
  EXPECT_EQ((2.0 * a).y, 4.0);
  EXPECT_EQ((a * 2.0).x, 2.0);
  EXPECT_EQ(dot(a, b), 1.0);
  EXPECT_EQ(cross(a, b), -7.0);        // b is clockwise from a
  EXPECT_EQ(cross(Vec2{1, 0}, Vec2{0, 1}), 1.0);
  EXPECT_EQ(length(Vec2{3, 4}), 5.0);
}

TEST(Vec2, DegreesRoundTrip) {
  EXPECT_DOUBLE_EQ(degreesOf(Vec2{1, 0}), 0.0);
  EXPECT_DOUBLE_EQ(degreesOf(Vec2{0, 1}), 90.0);
  EXPECT_DOUBLE_EQ(degreesOf(Vec2{-1, 0}), 180.0);
  EXPECT_DOUBLE_EQ(degreesOf(Vec2{0, -2}), -90.0);
  for (double deg : {-135.0, -30.0, 10.0, 45.0, 170.0}) {
    const Vec2 u = unitAtDegrees(deg);
    EXPECT_NEAR(length(u), 1.0, 1e-15);
    EXPECT_NEAR(degreesOf(u), deg, 1e-12);
  }
}

}  // namespace
}  // namespace fsdb
