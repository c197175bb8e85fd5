// Tests for geometry/core/vec3.h.
#include "geometry/core/vec3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fsdb {
namespace {

TEST(Vec3, Arithmetic) {
  const Vec3 a{1, 2, 3}, b{-4, 0.5, 2};
  EXPECT_EQ(a + b, (Vec3{-3, 2.5, 5}));
  EXPECT_EQ(a - b, (Vec3{5, 1.5, 1}));
  EXPECT_EQ(-a, (Vec3{-1, -2, -3}));
  EXPECT_EQ(2.0 * a, (Vec3{2, 4, 6}));
  EXPECT_EQ(a * 2.0, (Vec3{2, 4, 6}));
  EXPECT_EQ(a / 2.0, (Vec3{0.5, 1, 1.5}));
  EXPECT_TRUE(a != b);
  EXPECT_FALSE(a != a);
  EXPECT_EQ(Vec3{}, (Vec3{0, 0, 0}));
}

TEST(Vec3, DotAndCross) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(cross(x, y), z);
  EXPECT_EQ(cross(y, z), x);
  EXPECT_EQ(cross(z, x), y);
  const Vec3 a{1, 2, 3}, b{-4, 0.5, 2};
  EXPECT_DOUBLE_EQ(dot(a, b), 3.0);
  EXPECT_DOUBLE_EQ(dot(cross(a, b), a), 0.0);
  EXPECT_DOUBLE_EQ(dot(cross(a, b), b), 0.0);
}

TEST(Vec3, NormNeitherOverflowsNorUnderflows) {
  EXPECT_DOUBLE_EQ(norm({3, 4, 12}), 13.0);
  EXPECT_DOUBLE_EQ(norm({3e200, 4e200, 0}), 5e200);
  EXPECT_DOUBLE_EQ(norm({0, 3e-200, 4e-200}), 5e-200);
  EXPECT_EQ(norm({0, 0, 0}), 0.0);
  EXPECT_EQ(norm({-std::numeric_limits<double>::infinity(), 0, 1}),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(norm({0, std::numeric_limits<double>::infinity(), 0}),
            std::numeric_limits<double>::infinity());
}

TEST(Vec3, IsFinite) {
  EXPECT_TRUE(isFinite({1, -2, 1e300}));
  EXPECT_FALSE(isFinite({std::numeric_limits<double>::infinity(), 0, 0}));
  EXPECT_FALSE(isFinite({0, std::numeric_limits<double>::quiet_NaN(), 0}));
  EXPECT_FALSE(isFinite({0, 0, -std::numeric_limits<double>::infinity()}));
}

}  // namespace
TEST(Vec3, ComponentMinAndMaxTakeEachCoordinateApart) {
  const Vec3 a{1, -2, 3}, b{0, 5, 3};
  const Vec3 lo = componentMin(a, b), hi = componentMax(a, b);
  EXPECT_EQ(lo.x, 0);
  EXPECT_EQ(lo.y, -2);
  EXPECT_EQ(lo.z, 3);
  EXPECT_EQ(hi.x, 1);
  EXPECT_EQ(hi.y, 5);
  EXPECT_EQ(hi.z, 3);
  // The hull of a box with the empty box (+inf, -inf) is the box itself.
  const Vec3 inf{INFINITY, INFINITY, INFINITY};
  EXPECT_EQ(componentMin(inf, a).y, -2);
  EXPECT_EQ(componentMax(-inf, b).y, 5);
}

TEST(Vec3, BoxesMeetWhenTheyShareAPointTouchingIncluded) {
  EXPECT_TRUE(boxesMeet({0, 0, 0}, {1, 1, 1}, {0.5, 0.5, 0.5}, {2, 2, 2}));
  EXPECT_TRUE(boxesMeet({0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {2, 2, 2}));  // one corner
  EXPECT_TRUE(boxesMeet({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0, 0, 0}, {1, 1, 1}));  // a point inside
  EXPECT_FALSE(boxesMeet({0, 0, 0}, {1, 1, 1}, {1.5, 0, 0}, {2, 1, 1}));
  EXPECT_FALSE(boxesMeet({0, 0, 0}, {1, 1, 1}, {0, 0, -2}, {1, 1, -0.1}));
}

}  // namespace fsdb
