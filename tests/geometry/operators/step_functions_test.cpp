// Smooth unit step functions: Li & Tian, eq. 2-3; Li, eq. 4-8, 14-17 and Def. 3. Fast forms
// against the literal recursive definitions, closed forms, the stated properties, smoothness
// at the breakpoints, and parameter ranges.
#include "tests/geometry/expect_error.h"
#include "geometry/operators/step_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "tests/geometry/smoothness.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> samples(double lo, double hi, int steps) {
  std::vector<double> s;
  for (int i = 0; i <= steps; ++i) s.push_back(lo + (hi - lo) * i / steps);
  return s;
}

TEST(Heaviside, Eq2) {
  EXPECT_EQ(heaviside(-1e-300), 0.0);
  EXPECT_EQ(heaviside(0.0), 0.5);
  EXPECT_EQ(heaviside(3.0), 1.0);
}

// The literal recursions lose digits through their negative weights (|x| > n deep in the
// recursion tree), so agreement is checked to 1e-12 for the degrees where they are cheap.
TEST(LiTianStep, DynamicProgrammeEqualsLiteralRecursionEq2) {
  for (int n = 0; n <= 10; ++n)
    for (double x : samples(-n - 1.5, n + 1.5, 157))
      EXPECT_NEAR(liTianStep(n, x), reference::liTianStep(n, x), 1e-12) << n << " " << x;
}

TEST(LiTianStep, ClosedFormsForLowDegrees) {
  for (double x : samples(-3, 3, 121)) {
    double h1 = x <= -1 ? 0 : (x >= 1 ? 1 : (1 + x) / 2);
    EXPECT_NEAR(liTianStep(1, x), h1, 1e-15);
    // H_2 = (x+2)^2/8 on [-2, 0], 1 - (2-x)^2/8 on [0, 2]
    double h2 =
        x <= -2 ? 0 : (x <= 0 ? (x + 2) * (x + 2) / 8 : (x < 2 ? 1 - (2 - x) * (2 - x) / 8 : 1));
    EXPECT_NEAR(liTianStep(2, x), h2, 1e-15);
  }
}

TEST(LiTianStep, PropertiesAfterEq2) {
  for (int n = 1; n <= kMaxPolynomialStepDegree; ++n) {
    EXPECT_NEAR(liTianStep(n, 0.0), 0.5, 1e-15);  // property (4)
    double previous = 0.0;
    for (double x : samples(-n - 1.0, n + 1.0, 200)) {
      double v = liTianStep(n, x);
      EXPECT_NEAR(v + liTianStep(n, -x), 1.0, 1e-14);  // property (4)
      EXPECT_GE(v, previous - 1e-15);                  // property (3): nondecreasing
      if (x <= -n) {                                   // property (3): support [-n, n]
        EXPECT_EQ(v, 0.0);
      }
      if (x >= n) {
        EXPECT_EQ(v, 1.0);
      }
      previous = v;
    }
  }
}

TEST(LiTianStep, IsCnMinus1AtItsKnots) {
  // Knots at x = -n, -n+2, ..., n; pieces of width 2, differences over h = width/20 (small
  // enough to stay inside one piece, large enough that rounding stays below the 6th difference).
  for (int n = 2; n <= 6; ++n)
    for (int j = 0; j <= n; ++j) {
      double knot = -n + 2.0 * j;
      EXPECT_TRUE(
          testing::exactlyCkAt([n](double x) { return liTianStep(n, x); }, knot, n - 1, 0.1))
          << "n=" << n << " knot " << knot;
    }
}

TEST(LiTianStepRange, Eq3ScalesTheSupportToR) {
  for (int n : {1, 3, 6})
    for (double R : {0.25, 1.0, 7.0})
      for (double x : samples(-1.2 * R, 1.2 * R, 60)) {
        EXPECT_EQ(liTianStepRange(n, R, x), liTianStep(n, n * x / R));
        if (std::fabs(x) >= R) {
          EXPECT_EQ(liTianStepRange(n, R, x), x > 0 ? 1.0 : 0.0);
        }
      }
}

TEST(CardinalStep, DynamicProgrammeEqualsLiteralRecursionEq5) {
  for (int n = 0; n <= 10; ++n)
    for (double t : samples(-1.5, n + 1.5, 143))
      EXPECT_NEAR(cardinalStep(n, t), reference::cardinalStep(n, t), 1e-12) << n << " " << t;
}

TEST(PolynomialStep, Eq6EqualsLiteralAndDefinition2) {
  for (int n = 1; n <= 10; ++n)
    for (double t : samples(-1.3, 1.3, 131)) {
      double v = polynomialStep(n, t);
      EXPECT_NEAR(v, reference::polynomialStep(n, t), 1e-12);
      if (t < -1) {  // Def. 2 (1)
        EXPECT_EQ(v, 0.0);
      }
      if (t > 1) {  // Def. 2 (2)
        EXPECT_EQ(v, 1.0);
      }
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
  for (int n = 1; n <= kMaxPolynomialStepDegree; ++n) {
    double previous = 0.0;
    for (double t : samples(-1.0, 1.0, 400)) {
      double v = polynomialStep(n, t);
      EXPECT_GE(v, previous - 1e-15) << n;  // Def. 2 (3): nondecreasing
      previous = v;
    }
  }
}

TEST(PolynomialStep, Seed000HnIsSeed001HnWithSupportScaled) {
  // Li & Tian's H_n(x) == Li's H_n(x / n)
  for (int n = 1; n <= kMaxPolynomialStepDegree; ++n)
    for (double x : samples(-n - 0.5, n + 0.5, 97))
      EXPECT_NEAR(liTianStep(n, x), polynomialStep(n, x / n), 1e-14) << n << " " << x;
}

TEST(PolynomialStep, IsCnMinus1AtItsKnots) {
  // Knots at t = -1 + 2j/n; pieces of width 2/n, h = width/20.
  for (int n = 2; n <= 6; ++n)
    for (int j = 0; j <= n; ++j) {
      double knot = -1.0 + 2.0 * j / n;
      EXPECT_TRUE(testing::exactlyCkAt([n](double t) { return polynomialStep(n, t); }, knot, n - 1,
                                       0.1 / n))
          << "n=" << n << " knot " << knot;
    }
}

TEST(BSplineStep, ClosedFormEqualsQuadratureOfCoxDeBoorEq7) {
  for (int m = 1; m <= 12; ++m)
    for (double t : samples(-1.2, 1.2, 61))
      EXPECT_NEAR(bsplineStep(m, t), reference::bsplineStep(m, t), 1e-13) << m << " " << t;
}

TEST(BSplineStep, CubicIsEq8) {
  auto f = [](double t) {
    if (t <= 0) return 0.0;
    if (t <= 1) return t * t * t / 6;
    if (t <= 2) return -5.0 / 8 + 0.75 * t - (t - 1.5) * (t - 1.5) * (t - 1.5) / 3;
    if (t <= 3) return 1 - (3 - t) * (3 - t) * (3 - t) / 6;
    return 1.0;
  };
  for (double t : samples(-1.5, 1.5, 301))
    EXPECT_NEAR(bsplineStep(3, t), f(3 * (t + 1) / 2), 1e-15);
}

TEST(BSplineStep, EqualsPolynomialStepAsTheRecursionImplies) {
  for (int m = 1; m <= kMaxBSplineOrder; ++m)
    for (double t : samples(-1.1, 1.1, 111))
      EXPECT_NEAR(bsplineStep(m, t), polynomialStep(m, t), 1e-11) << m << " " << t;
}

TEST(CardinalBSpline, CoxDeBoorReferenceIsTheCardinalBSpline) {
  EXPECT_EQ(reference::cardinalBSpline(1, 0.5), 1.0);
  EXPECT_EQ(reference::cardinalBSpline(1, 1.0), 0.0);
  EXPECT_NEAR(reference::cardinalBSpline(2, 0.5), 0.5, 1e-15);  // hat
  EXPECT_NEAR(reference::cardinalBSpline(3, 1.5), 0.75, 1e-15);
  EXPECT_NEAR(reference::cardinalBSpline(4, 2.0), 2.0 / 3.0, 1e-15);
}

TEST(RisingCutoff, Eq16EqualsThetaRecursionEq14) {
  for (int n = 1; n <= kMaxRisingCutoffLevel; ++n)
    for (double t : samples(-1.3, 1.3, 131))
      EXPECT_NEAR(risingCutoff(n, t), reference::risingCutoff(n, t), 1e-14) << n << " " << t;
}

TEST(RisingCutoff, IsARisingCutoffAndAStep) {
  for (double t : samples(-1, 1, 50))
    EXPECT_NEAR(risingCutoff(1, t), std::sin(kPi / 4 * (1 + t)), 1e-15);
  for (int n = 1; n <= kMaxRisingCutoffLevel; ++n) {
    EXPECT_NEAR(risingCutoff(n, 0.0), std::sqrt(0.5), 1e-15);
    double previous = 0.0;
    for (double t : samples(-1.5, 1.5, 300)) {
      double r = risingCutoff(n, t), rm = risingCutoff(n, -t);
      EXPECT_NEAR(r * r + rm * rm, 1.0, 1e-14);  // eq. 9
      EXPECT_GE(r, previous);                    // nondecreasing
      if (t <= -1) {                             // eq. 10
        EXPECT_EQ(r, 0.0);
      }
      if (t >= 1) {
        EXPECT_EQ(r, 1.0);
      }
      previous = r;
      double s = risingCutoffSquared(n, t);
      EXPECT_NEAR(s, r * r, 1e-15);
      EXPECT_NEAR(s + risingCutoffSquared(n, -t), 1.0, 1e-14);  // antisymmetric about (0, 1/2)
    }
  }
}

TEST(RisingCutoff, HasTwoToTheNMinus1MinusOneVanishingDerivativesAtTheEnds) {
  // At -1, R_n(t) ~ c (1 + t)^(2^(n-1)): exactly 2^(n-1) - 1 vanishing derivatives, as stated
  // (R_1 C^0, R_2 C^1, R_3 C^3). At +1 the paper's count is a lower bound: R_1'(1) = 0 already,
  // and 1 - R_n(t) ~ c (1 - t)^(2^n), so R_n is C^(2^n - 1) there (R_1 C^1, R_2 C^3).
  int atMinusOne[] = {0, 1, 3};
  int atPlusOne[] = {1, 3};
  for (int n = 1; n <= 3; ++n) {
    auto r = [n](double t) { return risingCutoff(n, t); };
    EXPECT_TRUE(testing::exactlyCkAt(r, -1.0, atMinusOne[n - 1], 0.004)) << n;
    if (n <= 2) {
      EXPECT_TRUE(testing::exactlyCkAt(r, 1.0, atPlusOne[n - 1], 0.004)) << n;
    }
  }
}

TEST(Sigmoid, Eq17AndTheEpsilonBound) {
  EXPECT_EQ(sigmoidStep(3.0, 0.0), 0.5);
  EXPECT_NEAR(sigmoidStep(2.0, 0.7), 1 / (1 + std::exp(-1.4)), 1e-16);
  EXPECT_NEAR(sigmoidStep(2.0, -0.7), 1 / (1 + std::exp(1.4)), 1e-16);
  EXPECT_EQ(sigmoidStep(1.0, -1e6), 0.0);  // no overflow
  EXPECT_EQ(sigmoidStep(1.0, 1e6), 1.0);
  for (double epsilon : {0.4, 0.1, 1e-3, 1e-9}) {
    double bound = sigmoidAlphaBound(epsilon);
    EXPECT_NEAR(bound, std::log((1 - epsilon) / epsilon), 1e-12);
    double alpha = bound * 1.0001;
    for (double t : samples(-50, -1.0, 100)) EXPECT_LT(sigmoidStep(alpha, t), epsilon);
    for (double t : samples(1.0, 50, 100)) EXPECT_GT(sigmoidStep(alpha, t), 1 - epsilon);
    // and the bound is sharp: a smaller alpha misses it at t = -1
    EXPECT_GT(sigmoidStep(bound * 0.999, -1.0), epsilon);
  }
  EXPECT_LE(sigmoidAlphaBound(0.7), 0.0);  // any alpha works for epsilon >= 1/2
}

TEST(RisingRange, Def3ScalesTheRisingRange) {
  auto mu = [](double t) { return polynomialStep(3, t); };
  for (double epsilon : {0.05, 0.5, 4.0})
    for (double t : samples(-5, 5, 101)) {
      EXPECT_EQ(withRisingRange(mu, epsilon, t), mu(t / epsilon));
      if (t <= -epsilon) {
        EXPECT_EQ(withRisingRange(mu, epsilon, t), 0.0);
      }
      if (t >= epsilon) {
        EXPECT_EQ(withRisingRange(mu, epsilon, t), 1.0);
      }
    }
}

TEST(StepFunctions, ParametersOutsideRangeThrowWithTheirPath) {
  expectInvalidParameter([] { liTianStep(-1, 0.0); }, "n");
  expectInvalidParameter([] { liTianStep(kMaxPolynomialStepDegree + 1, 0.0); }, "n");
  expectInvalidParameter([] { liTianStepRange(0, 1.0, 0.0); }, "n");
  expectInvalidParameter([] { liTianStepRange(2, 0.0, 0.0); }, "R");
  expectInvalidParameter([] { cardinalStep(33, 0.0); }, "n");
  expectInvalidParameter([] { polynomialStep(0, 0.0); }, "n");
  expectInvalidParameter([] { bsplineStep(0, 0.0); }, "m");
  expectInvalidParameter([] { bsplineStep(kMaxBSplineOrder + 1, 0.0); }, "m");
  expectInvalidParameter([] { risingCutoff(0, 0.0); }, "n");
  expectInvalidParameter([] { risingCutoff(kMaxRisingCutoffLevel + 1, 0.0); }, "n");
  expectInvalidParameter([] { risingCutoffSquared(0, 0.0); }, "n");
  expectInvalidParameter([] { sigmoidStep(0.0, 0.0); }, "alpha");
  expectInvalidParameter([] { sigmoidAlphaBound(1.0); }, "epsilon");
  expectInvalidParameter([] { reference::liTianStep(-1, 0.0); }, "n");
  expectInvalidParameter([] { reference::cardinalStep(-1, 0.0); }, "n");
  expectInvalidParameter([] { reference::polynomialStep(0, 0.0); }, "n");
  expectInvalidParameter([] { reference::cardinalBSpline(0, 0.0); }, "m");
  expectInvalidParameter([] { reference::bsplineStep(0, 0.0); }, "m");
  expectInvalidParameter([] { reference::risingCutoff(0, 0.0); }, "n");
}

}  // namespace
}  // namespace fsdb
