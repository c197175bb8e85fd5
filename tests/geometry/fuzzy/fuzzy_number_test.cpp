#include "geometry/fuzzy/fuzzy_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "geometry/core/error.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using testing::uniform;

void expectError(const std::function<void()>& f, const std::string& code, const std::string& path) {
  try {
    f();
    FAIL() << "no error, expected " << code << " at " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
    EXPECT_FALSE(std::string(e.what()).empty());
  }
}

std::vector<Breakpoint> bp(std::initializer_list<Breakpoint> list) { return list; }

TEST(FuzzyNumber, FactoriesGiveCanonicalBreakpoints) {
  EXPECT_EQ(FuzzyNumber::crisp(2).breakpoints(), bp({{2, 0}, {2, 1}, {2, 0}}));
  EXPECT_EQ(FuzzyNumber::triangular(1, 2, 4).breakpoints(), bp({{1, 0}, {2, 1}, {4, 0}}));
  EXPECT_EQ(FuzzyNumber::trapezoidal(1, 2, 3, 4).breakpoints(), bp({{1, 0}, {2, 1}, {3, 1}, {4, 0}}));
  // Degenerate shapes collapse to the simpler ones.
  EXPECT_EQ(FuzzyNumber::triangular(2, 2, 2), FuzzyNumber::crisp(2));
  EXPECT_EQ(FuzzyNumber::trapezoidal(1, 2, 2, 4), FuzzyNumber::triangular(1, 2, 4));
  EXPECT_EQ(FuzzyNumber::trapezoidal(3, 3, 3, 3), FuzzyNumber::crisp(3));
  EXPECT_EQ(FuzzyNumber::triangular(1, 1, 3).breakpoints(), bp({{1, 0}, {1, 1}, {3, 0}}));
  EXPECT_EQ(FuzzyNumber::trapezoidal(1, 1, 3, 3).breakpoints(), bp({{1, 0}, {1, 1}, {3, 1}, {3, 0}}));
  EXPECT_EQ(FuzzyNumber(), FuzzyNumber::crisp(0));
  EXPECT_NE(FuzzyNumber::triangular(1, 2, 4), FuzzyNumber::triangular(1, 2, 5));
  EXPECT_FALSE(FuzzyNumber::crisp(1) != FuzzyNumber::crisp(1));
}

TEST(FuzzyNumber, FromPointsCanonicalises) {
  // Ends above 0 become vertical sides; collinear points and zero tails go.
  EXPECT_EQ(FuzzyNumber::fromPoints({{2, 1}}), FuzzyNumber::crisp(2));
  EXPECT_EQ(FuzzyNumber::fromPoints({{0, 1}, {1, 1}}), FuzzyNumber::trapezoidal(0, 0, 1, 1));
  EXPECT_EQ(FuzzyNumber::fromPoints({{-5, 0}, {0, 0}, {1, 0.5}, {2, 1}, {4, 0}, {9, 0}}),
            FuzzyNumber::triangular(0, 2, 4));
  EXPECT_EQ(FuzzyNumber::fromPoints({{0, 0}, {1, 0.3}, {1, 0.1}, {1, 0.3}, {2, 1}, {3, 0}}).breakpoints(),
            bp({{0, 0}, {1, 0.3}, {2, 1}, {3, 0}}));
  // A spike inside a jump keeps left limit, value and right limit.
  EXPECT_EQ(FuzzyNumber::fromPoints({{0, 0}, {1, 0.2}, {1, 1}, {1, 0.1}, {1, 0.5}, {2, 0}}).breakpoints(),
            bp({{0, 0}, {1, 0.2}, {1, 1}, {1, 0.5}, {2, 0}}));
}

TEST(FuzzyNumber, CanonicalFormIsAFixedPoint) {
  std::mt19937 rng(1);
  for (int i = 0; i < 300; ++i) {
    const FuzzyNumber a = testing::randomPoints(rng);
    EXPECT_EQ(FuzzyNumber::fromPoints(a.breakpoints()), a);
    EXPECT_EQ(a.breakpoints().front().mu, 0);
    EXPECT_EQ(a.breakpoints().back().mu, 0);
  }
}

TEST(FuzzyNumber, FactoryErrorsNameTheBadArgument) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  expectError([] { FuzzyNumber::triangular(3, 2, 4); }, errc::kInvalidDocument, "[1]");
  expectError([] { FuzzyNumber::triangular(1, 2, 1.5); }, errc::kInvalidDocument, "[2]");
  expectError([&] { FuzzyNumber::triangular(nan, 2, 3); }, errc::kInvalidDocument, "[0]");
  expectError([] { FuzzyNumber::trapezoidal(1, 2, 1.5, 4); }, errc::kInvalidDocument, "[2]");
  expectError([&] { FuzzyNumber::trapezoidal(1, 2, 3, inf); }, errc::kInvalidDocument, "[3]");
  expectError([&] { FuzzyNumber::crisp(nan); }, errc::kInvalidDocument, "");
  expectError([] { FuzzyNumber::fromPoints({}); }, errc::kInvalidDocument, "");
  expectError([] { FuzzyNumber::fromPoints({{0, 0}, {1, 0.8}, {2, 0}}); }, errc::kInvalidDocument, "");
  expectError([] { FuzzyNumber::fromPoints({{0, 0}, {1, 1.5}}); }, errc::kInvalidDocument, "[1][1]");
  expectError([] { FuzzyNumber::fromPoints({{0, -0.1}, {1, 1}}); }, errc::kInvalidDocument, "[0][1]");
  expectError([] { FuzzyNumber::fromPoints({{0, 0}, {2, 1}, {1, 0}}); }, errc::kInvalidDocument, "[2][0]");
  expectError([&] { FuzzyNumber::fromPoints({{0, 0}, {inf, 1}}); }, errc::kInvalidDocument, "[1][0]");
  try {
    FuzzyNumber::triangular(3, 2, 4);
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "triangular number needs l <= m <= r, got l=3 > m=2");
  }
}

TEST(FuzzyNumber, MembershipOfTriangleTrapezoidAndJumps) {
  const FuzzyNumber tri = FuzzyNumber::triangular(1, 2, 4);
  EXPECT_EQ(tri.membership(0), 0);
  EXPECT_EQ(tri.membership(1.5), 0.5);
  EXPECT_EQ(tri.membership(2), 1);
  EXPECT_EQ(tri.membership(3), 0.5);
  EXPECT_EQ(tri.membership(4), 0);
  EXPECT_EQ(tri.membership(std::nan("")), 0);
  const FuzzyNumber interval = FuzzyNumber::trapezoidal(1, 1, 3, 3);
  EXPECT_EQ(interval.membership(1), 1);  // the larger side of the jump
  EXPECT_EQ(interval.membership(3), 1);
  EXPECT_EQ(interval.membership(3.0001), 0);
  EXPECT_EQ(FuzzyNumber::crisp(2).membership(2), 1);
  EXPECT_EQ(FuzzyNumber::crisp(2).membership(2.0000001), 0);
}

TEST(FuzzyNumber, AlphaCutsOfClosedForms) {
  const FuzzyNumber tri = FuzzyNumber::triangular(1, 2, 4);
  // Sarwar & Akram: cut of a triangle = [l + a (m - l), r - a (r - m)]
  for (double a : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    EXPECT_DOUBLE_EQ(tri.alphaCut(a).lo, 1 + a * 1);
    EXPECT_DOUBLE_EQ(tri.alphaCut(a).hi, 4 - a * 2);
  }
  const FuzzyNumber trap = FuzzyNumber::trapezoidal(0, 1, 3, 7);
  EXPECT_EQ(trap.alphaCut(0.5), (Interval{0.5, 5}));
  EXPECT_EQ(trap.core(), (Interval{1, 3}));
  EXPECT_EQ(trap.support(), (Interval{0, 7}));
  EXPECT_EQ(FuzzyNumber::crisp(5).alphaCut(0.3), (Interval{5, 5}));
  EXPECT_EQ(FuzzyNumber::trapezoidal(1, 1, 3, 3).alphaCut(0.7), (Interval{1, 3}));
}

// Cuts of a number whose breakpoints span nearly all doubles stay finite and nested (the span
// b - a overflowed to infinity before).
TEST(FuzzyNumber, AlphaCutsOfAHugeSpanStayFinite) {
  const FuzzyNumber huge = FuzzyNumber::triangular(-1e308, 1e308, 1e308);
  Interval previous = huge.alphaCut(0);
  for (double a : {0.125, 0.25, 0.5, 0.75, 1.0}) {
    const Interval cut = huge.alphaCut(a);
    EXPECT_TRUE(std::isfinite(cut.lo) && std::isfinite(cut.hi)) << a;
    EXPECT_LE(cut.lo, cut.hi) << a;
    EXPECT_GE(cut.lo, previous.lo) << a;
    previous = cut;
  }
  EXPECT_DOUBLE_EQ(huge.alphaCut(0.5).lo, 0.0);
  EXPECT_EQ(huge.alphaCut(1), (Interval{1e308, 1e308}));
}

TEST(FuzzyNumber, StrongCutDiffersOnlyAtHorizontalPieces) {
  const FuzzyNumber a = FuzzyNumber::fromPoints({{0, 0}, {1, 0.5}, {2, 0.5}, {3, 1}, {4, 0}});
  EXPECT_EQ(a.alphaCut(0.5), (Interval{1, 3.5}));
  EXPECT_EQ(a.strongAlphaCut(0.5), (Interval{2, 3.5}));
  EXPECT_EQ(a.strongAlphaCut(0.25), a.alphaCut(0.25));
  EXPECT_EQ(a.strongAlphaCut(0), a.support());
  expectError([&] { a.strongAlphaCut(1); }, errc::kInvalidParameter, "alpha");
  expectError([&] { a.alphaCut(1.5); }, errc::kInvalidParameter, "alpha");
  expectError([&] { a.alphaCut(-0.1); }, errc::kInvalidParameter, "alpha");
  expectError([&] { a.alphaCut(std::nan("")); }, errc::kInvalidParameter, "alpha");
}

TEST(FuzzyNumber, NonConvexCutsAreHulls) {
  const FuzzyNumber twoHumps = FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 0}, {3, 0}, {4, 0.6}, {5, 0}});
  EXPECT_FALSE(twoHumps.isConvex());
  EXPECT_EQ(twoHumps.alphaCut(0.5), (Interval{0.5, 4 + 1.0 / 6}));
  EXPECT_NEAR(twoHumps.alphaCut(0.5).hi, 4 + 1.0 / 6, 1e-15);
  EXPECT_EQ(twoHumps.alphaCut(0.7), (Interval{0.7, 1.3}));
  EXPECT_EQ(twoHumps.core(), (Interval{1, 1}));
  EXPECT_EQ(twoHumps.support(), (Interval{0, 5}));
}

TEST(FuzzyNumber, CrispAndConvexPredicates) {
  EXPECT_TRUE(FuzzyNumber::crisp(1).isCrisp());
  EXPECT_FALSE(FuzzyNumber::triangular(0, 1, 2).isCrisp());
  EXPECT_TRUE(FuzzyNumber::crisp(1).isConvex());
  EXPECT_TRUE(FuzzyNumber::trapezoidal(0, 1, 2, 3).isConvex());
  EXPECT_TRUE(FuzzyNumber::fromPoints({{0, 0}, {1, 0.5}, {2, 0.5}, {3, 1}, {4, 0}}).isConvex());
  EXPECT_FALSE(FuzzyNumber::fromPoints({{0, 1}, {1, 0.2}, {2, 1}}).isConvex());
}

TEST(FuzzyNumber, CardinalityClosedForms) {
  std::mt19937 rng(3);
  for (int i = 0; i < 200; ++i) {
    const double a = uniform(rng, -5, 5), b = a + uniform(rng, 0, 3), c = b + uniform(rng, 0, 3),
                 d = c + uniform(rng, 0, 3);
    EXPECT_NEAR(FuzzyNumber::triangular(a, b, c).cardinality(), (c - a) / 2, 1e-12);
    EXPECT_NEAR(FuzzyNumber::trapezoidal(a, b, c, d).cardinality(), ((d - a) + (c - b)) / 2, 1e-12);
  }
  EXPECT_EQ(FuzzyNumber::crisp(4).cardinality(), 0);
}

// alpha1 < alpha2 => cut(alpha2) ⊆ cut(alpha1), and the cut ends have the level's membership.
TEST(FuzzyNumber, RandomAlphaCutsAreNested) {
  std::mt19937 rng(4);
  for (int i = 0; i < 300; ++i) {
    const FuzzyNumber a = i % 3 == 0   ? testing::randomTriOrTrap(rng)
                          : i % 3 == 1 ? testing::randomConvexPoints(rng)
                                       : testing::randomPoints(rng);
    for (int k = 0; k < 20; ++k) {
      double a1 = uniform(rng, 0, 1), a2 = uniform(rng, 0, 1);
      if (a1 > a2) std::swap(a1, a2);
      const Interval c1 = a.alphaCut(a1), c2 = a.alphaCut(a2);
      EXPECT_TRUE(contains(c1, c2)) << a1 << " " << a2;
      EXPECT_TRUE(contains(a.support(), c1));
      if (a1 > 0) {
        EXPECT_GE(a.membership(c1.lo), a1 - 1e-12);
        EXPECT_GE(a.membership(c1.hi), a1 - 1e-12);
        EXPECT_LT(a.membership(c1.lo - 1e-9), a1);
        EXPECT_LT(a.membership(c1.hi + 1e-9), a1);
      }
    }
    EXPECT_TRUE(contains(a.core(), a.core()));
    EXPECT_EQ(a.membership(a.core().lo), 1);
  }
}

TEST(FuzzyNumber, FromAlphaCutsInvertsAlphaCut) {
  std::mt19937 rng(5);
  for (int i = 0; i < 200; ++i) {
    const FuzzyNumber a = testing::randomConvexPoints(rng);
    std::vector<double> alphas;
    std::vector<Interval> cuts;
    std::vector<double> levels = {0, 1};
    for (const auto& p : a.breakpoints()) levels.push_back(p.mu);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    for (double alpha : levels) {
      alphas.push_back(alpha);
      cuts.push_back(a.alphaCut(alpha));
      if (alpha < 1 && a.strongAlphaCut(alpha) != a.alphaCut(alpha)) {
        alphas.push_back(alpha);
        cuts.push_back(a.strongAlphaCut(alpha));
      }
    }
    const FuzzyNumber b = FuzzyNumber::fromAlphaCuts(alphas, cuts);
    ASSERT_EQ(a.breakpoints().size(), b.breakpoints().size());
    for (size_t k = 0; k < a.breakpoints().size(); ++k) {
      EXPECT_NEAR(a.breakpoints()[k].x, b.breakpoints()[k].x, 1e-12);
      EXPECT_EQ(a.breakpoints()[k].mu, b.breakpoints()[k].mu);
    }
  }
  // A lowest level above 0 gives vertical sides.
  EXPECT_EQ(FuzzyNumber::fromAlphaCuts({0.5, 1}, {{0, 4}, {2, 2}}),
            FuzzyNumber::fromPoints({{0, 0}, {0, 0.5}, {2, 1}, {4, 0.5}, {4, 0}}));
}

TEST(FuzzyNumber, FromAlphaCutsRejectsBadInput) {
  expectError([] { FuzzyNumber::fromAlphaCuts({}, {}); }, errc::kInvalidParameter, "alphas");
  expectError([] { FuzzyNumber::fromAlphaCuts({0, 1}, {{0, 1}}); }, errc::kInvalidParameter, "alphas");
  expectError([] { FuzzyNumber::fromAlphaCuts({0, 0.5}, {{0, 2}, {1, 1}}); }, errc::kInvalidParameter, "alphas[1]");
  expectError(
      [] {
        FuzzyNumber::fromAlphaCuts({0.5, 0, 1}, {{0, 2}, {0, 2}, {1, 1}});
      },
      errc::kInvalidParameter, "alphas[1]");
  expectError(
      [] {
        FuzzyNumber::fromAlphaCuts({0, 0, 0, 1}, {{0, 2}, {0, 2}, {0, 2}, {1, 1}});
      },
      errc::kInvalidParameter, "alphas[2]");
  expectError([] { FuzzyNumber::fromAlphaCuts({-1, 1}, {{0, 2}, {1, 1}}); }, errc::kInvalidParameter, "alphas[0]");
  expectError([] { FuzzyNumber::fromAlphaCuts({0, 1}, {{0, 2}, {3, 1}}); }, errc::kInvalidParameter, "cuts[1]");
  expectError([] { FuzzyNumber::fromAlphaCuts({0, 1}, {{0, 2}, {3, 4}}); }, errc::kInvalidParameter, "cuts[1]");
}

}  // namespace
}  // namespace fsdb
