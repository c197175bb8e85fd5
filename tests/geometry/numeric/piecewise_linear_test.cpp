#include "geometry/numeric/piecewise_linear.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

// Rises to 1 on [0, 1], flat to 2, jumps down to 0.25 at 2, spikes to 0.9 at 3 (left 0.25,
// right 0.5), falls to 0 at 4.
const std::vector<Breakpoint> kJumpy = {
    {0, 0}, {1, 1}, {2, 1}, {2, 0.25}, {3, 0.25}, {3, 0.9}, {3, 0.5}, {4, 0}};

TEST(PiecewiseLinear, ValueAtInterpolatesAndTakesTheLargerSideAtJumps) {
  EXPECT_EQ(valueAt(kJumpy, -1), 0);
  EXPECT_EQ(valueAt(kJumpy, 0.5), 0.5);
  EXPECT_EQ(valueAt(kJumpy, 2), 1);      // jump down: the value is the upper side
  EXPECT_EQ(valueAt(kJumpy, 3), 0.9);    // spike
  EXPECT_EQ(valueAt(kJumpy, 3.5), 0.25);
  EXPECT_EQ(valueAt(kJumpy, 4), 0);
  EXPECT_EQ(valueAt(kJumpy, 5), 0);
  EXPECT_EQ(valueAt(kJumpy, std::nan("")), 0);
  EXPECT_EQ(valueAt({}, 1), 0);
}

TEST(PiecewiseLinear, OneSidedLimits) {
  EXPECT_EQ(leftLimit(kJumpy, 2), 1);
  EXPECT_EQ(rightLimit(kJumpy, 2), 0.25);
  EXPECT_EQ(leftLimit(kJumpy, 3), 0.25);
  EXPECT_EQ(rightLimit(kJumpy, 3), 0.5);
  EXPECT_EQ(leftLimit(kJumpy, 0.5), 0.5);
  EXPECT_EQ(rightLimit(kJumpy, 0.5), 0.5);
  // Outside the list the function is 0, so the ends are jumps when mu > 0 there.
  const std::vector<Breakpoint> box = {{0, 1}, {1, 1}};
  EXPECT_EQ(leftLimit(box, 0), 0);
  EXPECT_EQ(rightLimit(box, 0), 1);
  EXPECT_EQ(leftLimit(box, 1), 1);
  EXPECT_EQ(rightLimit(box, 1), 0);
}

TEST(PiecewiseLinear, AreaAndHeight) {
  EXPECT_DOUBLE_EQ(area(kJumpy), 0.5 + 1 + 0.25 + 0.25);
  EXPECT_EQ(height(kJumpy), 1);
  EXPECT_EQ(area({}), 0);
  EXPECT_EQ(height({}), 0);
  EXPECT_EQ(height({{0, 0.3}, {1, 0.2}}), 0.3);
}

TEST(PiecewiseLinear, CheckRejectsMalformedLists) {
  EXPECT_NO_THROW(checkPiecewiseLinear(kJumpy));
  try {
    checkPiecewiseLinear({{0, 0}, {2, 1}, {1, 0}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "[2]");
  }
  try {
    checkPiecewiseLinear({{0, 0}, {1, std::nan("")}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "[1]");
  }
}

TEST(PiecewiseLinear, MinAndMaxAddCrossings) {
  const std::vector<Breakpoint> up = {{0, 0}, {2, 1}};
  const std::vector<Breakpoint> down = {{0, 1}, {2, 0}};
  const auto lo = pointwiseMin(up, down);
  EXPECT_DOUBLE_EQ(valueAt(lo, 1), 0.5);
  EXPECT_DOUBLE_EQ(area(lo), 0.5);
  const auto hi = pointwiseMax(up, down);
  EXPECT_DOUBLE_EQ(valueAt(hi, 1), 0.5);
  EXPECT_DOUBLE_EQ(area(hi), 1.5);
}

std::vector<Breakpoint> randomFunction(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Breakpoint> f;
  double x = -3 + 2 * u(rng);
  const int n = 2 + static_cast<int>(8 * u(rng));
  for (int i = 0; i < n; ++i) {
    x += u(rng) < 0.15 ? 0.0 : 0.1 + u(rng);
    f.push_back({x, u(rng)});
  }
  return f;
}

// min / max agree with the pointwise definition everywhere (off the breakpoints, where the
// one-sided limits decide) and their areas with a fine Riemann sum.
TEST(PiecewiseLinear, RandomMinMaxMatchPointwiseDefinition) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const auto f = randomFunction(rng), g = randomFunction(rng);
    const auto lo = pointwiseMin(f, g), hi = pointwiseMax(f, g);
    EXPECT_NO_THROW(checkPiecewiseLinear(lo));
    for (int k = 0; k < 50; ++k) {
      const double x = -4 + 16 * u(rng);
      EXPECT_NEAR(valueAt(lo, x), std::min(valueAt(f, x), valueAt(g, x)), 1e-12);
      EXPECT_NEAR(valueAt(hi, x), std::max(valueAt(f, x), valueAt(g, x)), 1e-12);
    }
    double sumLo = 0, sumHi = 0;
    const int n = 200000;
    const double a = -4, b = 14, h = (b - a) / n;
    for (int i = 0; i < n; ++i) {
      const double x = a + (i + 0.5) * h;
      sumLo += h * std::min(valueAt(f, x), valueAt(g, x));
      sumHi += h * std::max(valueAt(f, x), valueAt(g, x));
    }
    EXPECT_NEAR(area(lo), sumLo, 1e-4);
    EXPECT_NEAR(area(hi), sumHi, 1e-4);
  }
}

TEST(PiecewiseLinear, BreakpointEquality) {
  EXPECT_TRUE((Breakpoint{1, 0.5}) == (Breakpoint{1, 0.5}));
  EXPECT_TRUE((Breakpoint{1, 0.5}) != (Breakpoint{1, 0.25}));
}

}  // namespace
}  // namespace fsdb
