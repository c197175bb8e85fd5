#include "geometry/fuzzy/fuzzy_arithmetic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <random>

#include "geometry/core/error.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using testing::uniform;

// sup over x in [lo, hi] of f(x): a grid, then a finer grid around the best point.
double supremum(const std::function<double(double)>& f, double lo, double hi) {
  const int n = 2000;
  double best = 0, bestX = lo;
  for (int i = 0; i <= n; ++i) {
    const double x = lo + (hi - lo) * i / n;
    if (f(x) > best) best = f(x), bestX = x;
  }
  const double h = (hi - lo) / n;
  for (int i = 0; i <= n; ++i) {
    const double x = std::clamp(bestX - 2 * h + 4 * h * i / n, lo, hi);
    best = std::max(best, f(x));
  }
  return best;
}

enum class Op { kAdd, kSub, kMul, kDiv, kMin, kMax };

// Zadeh's extension principle by brute force: mu_{A op B}(z) = sup_{x op y = z} min(mu_A(x), mu_B(y)).
double bruteForce(const FuzzyNumber& a, const FuzzyNumber& b, Op op, double z) {
  const Interval sa = a.support(), sb = b.support();
  auto muA = [&a](double x) { return a.membership(x); };
  auto muB = [&b](double y) { return b.membership(y); };
  switch (op) {
    case Op::kAdd:
      return supremum([&](double x) { return std::min(muA(x), muB(z - x)); }, sa.lo, sa.hi);
    case Op::kSub:
      return supremum([&](double x) { return std::min(muA(x), muB(x - z)); }, sa.lo, sa.hi);
    // Both parametrisations of x * y = z (or x / y = z) give lower bounds of the supremum;
    // each is accurate where the other's inner function is steep.
    case Op::kMul:
      return std::max(
          supremum([&](double x) { return x == 0 ? (z == 0 ? muA(0) : 0.0)
                                                 : std::min(muA(x), muB(z / x)); },
                   sa.lo, sa.hi),
          supremum([&](double y) { return y == 0 ? (z == 0 ? muB(0) : 0.0)
                                                 : std::min(muA(z / y), muB(y)); },
                   sb.lo, sb.hi));
    case Op::kDiv:
      return std::max(
          supremum([&](double x) { return std::min(muA(x), muB(x / z)); }, sa.lo, sa.hi),
          supremum([&](double y) { return std::min(muA(z * y), muB(y)); }, sb.lo, sb.hi));
    case Op::kMin:
    case Op::kMax: {
      // z = min(x, y): either x = z and y >= z, or y = z and x >= z (mirrored for max).
      const bool isMin = op == Op::kMin;
      auto beyond = [&](const std::function<double(double)>& mu, Interval s) {
        if (isMin) return z > s.hi ? 0.0 : supremum(mu, std::max(z, s.lo), s.hi);
        return z < s.lo ? 0.0 : supremum(mu, s.lo, std::min(z, s.hi));
      };
      return std::max(std::min(muA(z), beyond(muB, sb)), std::min(beyond(muA, sa), muB(z)));
    }
  }
  return 0;
}

FuzzyNumber apply(const FuzzyNumber& a, const FuzzyNumber& b, Op op) {
  switch (op) {
    case Op::kAdd: return add(a, b);
    case Op::kSub: return subtract(a, b);
    case Op::kMul: return multiply(a, b);
    case Op::kDiv: return divide(a, b);
    case Op::kMin: return min(a, b);
    case Op::kMax: return max(a, b);
  }
  return a;
}

void checkAgainstBruteForce(Op op, double tolerance, unsigned seed) {
  std::mt19937 rng(seed);
  double worst = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const FuzzyNumber a = testing::randomTriOrTrap(rng);
    FuzzyNumber b = testing::randomTriOrTrap(rng);
    if (op == Op::kDiv && contains(b.support(), 0.0)) b = add(b, FuzzyNumber::crisp(12));
    const FuzzyNumber r = apply(a, b, op);
    const Interval s = r.support();
    for (int k = 0; k < 25; ++k) {
      const double z = uniform(rng, s.lo - 0.1 * width(s), s.hi + 0.1 * width(s));
      const double expected = bruteForce(a, b, op, z);
      worst = std::max(worst, std::abs(r.membership(z) - expected));
      ASSERT_NEAR(r.membership(z), expected, tolerance) << "trial " << trial << " z=" << z;
    }
  }
  ::testing::Test::RecordProperty("worst_error", std::to_string(worst));
  std::printf("worst |mu - brute force| = %.3g\n", worst);
}

TEST(FuzzyArithmetic, AddMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kAdd, 1e-4, 1); }
TEST(FuzzyArithmetic, SubtractMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kSub, 1e-4, 2); }
TEST(FuzzyArithmetic, MultiplyMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kMul, 5e-4, 3); }
TEST(FuzzyArithmetic, DivideMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kDiv, 5e-4, 4); }
TEST(FuzzyArithmetic, MinMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kMin, 1e-4, 5); }
TEST(FuzzyArithmetic, MaxMatchesExtensionPrinciple) { checkAgainstBruteForce(Op::kMax, 1e-4, 6); }

TEST(FuzzyArithmetic, AddAndSubtractOfTrianglesAreExact) {
  const FuzzyNumber a = FuzzyNumber::triangular(1, 2, 3), b = FuzzyNumber::triangular(2, 4, 5);
  EXPECT_EQ(a + b, FuzzyNumber::triangular(3, 6, 8));
  EXPECT_EQ(b - a, FuzzyNumber::triangular(-1, 2, 4));
  EXPECT_EQ(a + FuzzyNumber::trapezoidal(0, 1, 2, 4), FuzzyNumber::trapezoidal(1, 3, 4, 7));
  EXPECT_EQ(a + FuzzyNumber::crisp(10), FuzzyNumber::triangular(11, 12, 13));
}

// The cuts of A + B and A - B equal the interval sums at every alpha, not only at breakpoints.
TEST(FuzzyArithmetic, AddAndSubtractAreExactAtEveryLevel) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng), b = testing::randomConvexPoints(rng);
    const FuzzyNumber sum = a + b, difference = a - b;
    for (int k = 0; k < 30; ++k) {
      const double alpha = k == 0 ? 0.0 : uniform(rng, 0, 1);
      const Interval s = add(a.alphaCut(alpha), b.alphaCut(alpha));
      const Interval d = sub(a.alphaCut(alpha), b.alphaCut(alpha));
      EXPECT_NEAR(sum.alphaCut(alpha).lo, s.lo, 1e-9);
      EXPECT_NEAR(sum.alphaCut(alpha).hi, s.hi, 1e-9);
      EXPECT_NEAR(difference.alphaCut(alpha).lo, d.lo, 1e-9);
      EXPECT_NEAR(difference.alphaCut(alpha).hi, d.hi, 1e-9);
    }
  }
}

// Horizontal pieces (strong cut != closed cut) survive: a shift is exact on any convex shape.
TEST(FuzzyArithmetic, HorizontalPiecesAreKept) {
  const FuzzyNumber a = FuzzyNumber::fromPoints({{0, 0}, {1, 0.5}, {2, 0.5}, {3, 1}, {4, 0}});
  EXPECT_EQ(a + FuzzyNumber::crisp(10),
            FuzzyNumber::fromPoints({{10, 0}, {11, 0.5}, {12, 0.5}, {13, 1}, {14, 0}}));
}

TEST(FuzzyArithmetic, MinMaxAreExactAtEveryLevel) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 200; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng), b = testing::randomConvexPoints(rng);
    const FuzzyNumber lo = min(a, b), hi = max(a, b);
    for (int k = 0; k < 30; ++k) {
      const double alpha = uniform(rng, 0, 1);
      const Interval l = min(a.alphaCut(alpha), b.alphaCut(alpha));
      const Interval h = max(a.alphaCut(alpha), b.alphaCut(alpha));
      EXPECT_NEAR(lo.alphaCut(alpha).lo, l.lo, 1e-9);
      EXPECT_NEAR(lo.alphaCut(alpha).hi, l.hi, 1e-9);
      EXPECT_NEAR(hi.alphaCut(alpha).lo, h.lo, 1e-9);
      EXPECT_NEAR(hi.alphaCut(alpha).hi, h.hi, 1e-9);
    }
  }
}

// Multiply and divide are exact at the refinement levels k/64 (and at breakpoint levels).
TEST(FuzzyArithmetic, MultiplyAndDivideAreExactAtSampledLevels) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 100; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng), b = testing::randomConvexPoints(rng);
    const FuzzyNumber divisor = contains(b.support(), 0.0) ? b + FuzzyNumber::crisp(20) : b;
    const FuzzyNumber product = a * b, quotient = a / divisor;
    for (int k = 0; k <= kArithmeticRefinementLevels; ++k) {
      const double alpha = static_cast<double>(k) / kArithmeticRefinementLevels;
      const Interval p = mul(a.alphaCut(alpha), b.alphaCut(alpha));
      const Interval q = div(a.alphaCut(alpha), divisor.alphaCut(alpha));
      EXPECT_NEAR(product.alphaCut(alpha).lo, p.lo, 1e-9 * (1 + std::abs(p.lo)));
      EXPECT_NEAR(product.alphaCut(alpha).hi, p.hi, 1e-9 * (1 + std::abs(p.hi)));
      EXPECT_NEAR(quotient.alphaCut(alpha).lo, q.lo, 1e-9 * (1 + std::abs(q.lo)));
      EXPECT_NEAR(quotient.alphaCut(alpha).hi, q.hi, 1e-9 * (1 + std::abs(q.hi)));
    }
  }
}

TEST(FuzzyArithmetic, Commutativity) {
  std::mt19937 rng(10);
  for (int trial = 0; trial < 100; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng), b = testing::randomConvexPoints(rng);
    EXPECT_EQ(a + b, b + a);
    EXPECT_EQ(a * b, b * a);
    EXPECT_EQ(min(a, b), min(b, a));
    EXPECT_EQ(max(a, b), max(b, a));
  }
}

// A - A is not crisp 0 (the extension principle forgets that both are the same variable),
// but 0 lies in its core and it is symmetric about 0.
TEST(FuzzyArithmetic, SelfDifferenceHoldsZeroInItsCore) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng);
    const FuzzyNumber d = a - a;
    EXPECT_TRUE(contains(d.core(), 0.0));
    EXPECT_NEAR(d.support().lo, -d.support().hi, 1e-12);
    EXPECT_NEAR(width(d.support()), 2 * width(a.support()), 1e-9);
  }
}

TEST(FuzzyArithmetic, DivisionByANumberAroundZeroIsADomainError) {
  const FuzzyNumber a = FuzzyNumber::triangular(1, 2, 3);
  for (const FuzzyNumber& b :
       {FuzzyNumber::triangular(-1, 1, 2), FuzzyNumber::triangular(0, 1, 2),
        FuzzyNumber::triangular(-2, -1, 0), FuzzyNumber::crisp(0)}) {
    try {
      a / b;
      FAIL() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kDomainError);
      EXPECT_EQ(e.path(), "divisor");
    }
  }
  EXPECT_NO_THROW(divide(a, FuzzyNumber::triangular(0.5, 1, 2)));
}

TEST(FuzzyArithmetic, ScaleAndNegateAreExact) {
  EXPECT_EQ(scale(FuzzyNumber::triangular(1, 2, 4), 3), FuzzyNumber::triangular(3, 6, 12));
  EXPECT_EQ(scale(FuzzyNumber::triangular(1, 2, 4), -2), FuzzyNumber::triangular(-8, -4, -2));
  EXPECT_EQ(scale(FuzzyNumber::triangular(1, 2, 4), 0), FuzzyNumber::crisp(0));
  EXPECT_EQ(negate(FuzzyNumber::trapezoidal(-1, 0, 2, 3)), FuzzyNumber::trapezoidal(-3, -2, 0, 1));
  EXPECT_EQ(-FuzzyNumber::crisp(0), FuzzyNumber::crisp(0));
  // Non-convex shapes keep their humps under scaling.
  const FuzzyNumber humps = FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 0}, {3, 0.5}, {4, 0}});
  EXPECT_EQ(negate(negate(humps)), humps);
  EXPECT_FALSE(scale(humps, -0.5).isConvex());
  EXPECT_EQ(scale(humps, -0.5).membership(-1.5), 0.5);
  try {
    scale(humps, std::nan(""));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "k");
  }
}

TEST(FuzzyArithmetic, MultiplyByCrispIsScale) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 50; ++trial) {
    const FuzzyNumber a = testing::randomConvexPoints(rng);
    const double k = uniform(rng, -3, 3);
    const FuzzyNumber product = a * FuzzyNumber::crisp(k), scaled = scale(a, k);
    for (double alpha : {0.0, 0.3, 0.7, 1.0}) {
      EXPECT_NEAR(product.alphaCut(alpha).lo, scaled.alphaCut(alpha).lo, 1e-9);
      EXPECT_NEAR(product.alphaCut(alpha).hi, scaled.alphaCut(alpha).hi, 1e-9);
    }
  }
}

TEST(FuzzyArithmetic, OperatorsMatchFunctions) {
  const FuzzyNumber a = FuzzyNumber::triangular(1, 2, 3), b = FuzzyNumber::trapezoidal(4, 5, 6, 8);
  EXPECT_EQ(a + b, add(a, b));
  EXPECT_EQ(a - b, subtract(a, b));
  EXPECT_EQ(a * b, multiply(a, b));
  EXPECT_EQ(a / b, divide(a, b));
  EXPECT_EQ(-a, negate(a));
}

// Non-convex operands act through their convex hulls.
TEST(FuzzyArithmetic, NonConvexOperandsUseTheirHull) {
  const FuzzyNumber humps = FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 0}, {3, 0.5}, {4, 0}});
  const FuzzyNumber hull = FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {1.5, 0.5}, {3, 0.5}, {4, 0}});
  EXPECT_EQ(humps + FuzzyNumber::crisp(0), hull);
}

}  // namespace
}  // namespace fsdb
