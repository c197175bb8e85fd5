#include "geometry/numeric/interval.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

TEST(Interval, AddSub) {
  EXPECT_EQ(add({1, 2}, {10, 20}), (Interval{11, 22}));
  EXPECT_EQ(sub({1, 2}, {10, 20}), (Interval{-19, -8}));
}

TEST(Interval, MulTakesTheCornerExtremes) {
  EXPECT_EQ(mul({1, 2}, {3, 4}), (Interval{3, 8}));
  EXPECT_EQ(mul({-1, 2}, {3, 4}), (Interval{-4, 8}));
  EXPECT_EQ(mul({-2, -1}, {-4, 3}), (Interval{-6, 8}));
}

TEST(Interval, Div) {
  EXPECT_EQ(div({1, 2}, {4, 8}), (Interval{0.125, 0.5}));
  EXPECT_EQ(div({-1, 2}, {-2, -1}), (Interval{-2, 1}));
}

TEST(Interval, DivByIntervalHoldingZeroIsADomainError) {
  for (Interval b : {Interval{-1, 1}, Interval{0, 1}, Interval{-1, 0}, Interval{0, 0}}) {
    try {
      div({1, 2}, b);
      FAIL() << "no error for [" << b.lo << ", " << b.hi << "]";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kDomainError);
      EXPECT_EQ(e.path(), "divisor");
    }
  }
}

TEST(Interval, MinMax) {
  EXPECT_EQ(min({1, 5}, {2, 3}), (Interval{1, 3}));
  EXPECT_EQ(max({1, 5}, {2, 3}), (Interval{2, 5}));
}

TEST(Interval, ContainsWidthHull) {
  EXPECT_TRUE(contains(Interval{1, 2}, 1.0));
  EXPECT_TRUE(contains(Interval{1, 2}, 2.0));
  EXPECT_FALSE(contains(Interval{1, 2}, 2.5));
  EXPECT_TRUE(contains(Interval{0, 3}, Interval{1, 2}));
  EXPECT_TRUE(contains(Interval{0, 3}, Interval{0, 3}));
  EXPECT_FALSE(contains(Interval{0, 3}, Interval{1, 4}));
  EXPECT_EQ(width(Interval{1, 3.5}), 2.5);
  EXPECT_EQ(hull({1, 2}, {4, 5}), (Interval{1, 5}));
  EXPECT_TRUE(Interval({1, 2}) != Interval({1, 3}));
}

// Inclusion and tightness: op(x, y) lies in op(a, b) for x in a, y in b, and the result's
// ends are reached at corners.
TEST(Interval, RandomInclusionAndTightness) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-5, 5);
  using Op = std::function<Interval(const Interval&, const Interval&)>;
  using Scalar = std::function<double(double, double)>;
  const std::vector<std::pair<Op, Scalar>> ops = {
      {[](auto& a, auto& b) { return add(a, b); }, [](double x, double y) { return x + y; }},
      {[](auto& a, auto& b) { return sub(a, b); }, [](double x, double y) { return x - y; }},
      {[](auto& a, auto& b) { return mul(a, b); }, [](double x, double y) { return x * y; }},
      {[](auto& a, auto& b) { return div(a, b); }, [](double x, double y) { return x / y; }},
      {[](auto& a, auto& b) { return min(a, b); }, [](double x, double y) { return std::min(x, y); }},
      {[](auto& a, auto& b) { return max(a, b); }, [](double x, double y) { return std::max(x, y); }},
  };
  for (int trial = 0; trial < 500; ++trial) {
    double a0 = u(rng), a1 = u(rng), b0 = u(rng), b1 = u(rng);
    Interval a{std::min(a0, a1), std::max(a0, a1)}, b{std::min(b0, b1), std::max(b0, b1)};
    if (contains(b, 0.0)) b = {b.hi + 0.1, b.hi + 1};  // keep division defined
    for (const auto& [op, f] : ops) {
      const Interval r = op(a, b);
      double lo = 1e300, hi = -1e300;
      for (double x : {a.lo, a.hi}) {
        for (double y : {b.lo, b.hi}) {
          lo = std::min(lo, f(x, y));
          hi = std::max(hi, f(x, y));
        }
      }
      EXPECT_DOUBLE_EQ(r.lo, lo);
      EXPECT_DOUBLE_EQ(r.hi, hi);
      for (int k = 0; k < 20; ++k) {
        const double x = a.lo + (a.hi - a.lo) * (k / 19.0);
        const double y = b.hi - (b.hi - b.lo) * ((k * 7 % 20) / 19.0);
        EXPECT_TRUE(contains(Interval{r.lo - 1e-12, r.hi + 1e-12}, f(x, y)));
      }
    }
  }
}

}  // namespace
}  // namespace fsdb
