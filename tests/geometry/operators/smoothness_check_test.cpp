// The finite-difference C^k checker of smoothness.h on functions of known smoothness, so that
// the smoothness tests of the operators are known to be able to fail.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/geometry/smoothness.h"

namespace fsdb::testing {
namespace {

double truncatedPower(double x, int p) { return x > 0 ? std::pow(x, p) : 0.0; }

TEST(SmoothnessCheck, FindsTheExactOrderOfTruncatedPowers) {
  // (x)_+^p is C^(p-1) at 0 with a jump of p! in the p-th derivative.
  for (int p = 1; p <= 6; ++p) {
    auto f = [p](double x) { return 1.0 + 0.3 * x + truncatedPower(x, p); };
    EXPECT_TRUE(exactlyCkAt(f, 0.0, p - 1, 0.05)) << p;
    EXPECT_FALSE(exactlyCkAt(f, 0.0, p, 0.05)) << p;  // claims one order too many
    if (p >= 2) {
      EXPECT_FALSE(exactlyCkAt(f, 0.0, p - 2, 0.05)) << p;  // and one too few
    }
  }
}

TEST(SmoothnessCheck, ContinuityAndJumpOfSingleDerivatives) {
  auto absolute = [](double x) { return std::fabs(x); };
  EXPECT_TRUE(derivativeContinuousAt(absolute, 0.0, 0, 0.01));
  EXPECT_TRUE(derivativeJumpsAt(absolute, 0.0, 1, 0.01));
  EXPECT_FALSE(derivativeContinuousAt(absolute, 0.0, 1, 0.01));
  auto smooth = [](double x) { return std::sin(3 * x); };  // no breakpoint: nothing jumps
  for (int k = 0; k <= 4; ++k) {
    EXPECT_TRUE(derivativeContinuousAt(smooth, 0.2, k, 0.01)) << k;
    EXPECT_FALSE(derivativeJumpsAt(smooth, 0.2, k, 0.01)) << k;
  }
  EXPECT_FALSE(exactlyCkAt(smooth, 0.2, 3, 0.01));
}

TEST(SmoothnessCheck, OneSidedDerivativesOfAPolynomial) {
  auto cubic = [](double x) { return x * x * x; };
  EXPECT_NEAR(oneSidedDerivative(cubic, 1.0, 3, 0.1, +1), 6.0, 1e-9);
  EXPECT_NEAR(oneSidedDerivative(cubic, 1.0, 3, 0.1, -1), 6.0, 1e-9);
  EXPECT_NEAR(oneSidedDerivative(cubic, 1.0, 1, 1e-6, +1), 3.0, 1e-5);
  EXPECT_NEAR(derivativeGap(cubic, 1.0, 2, 0.1), 6.0 * 0.1 * 2, 1e-9);  // (k/2) h (f'''+ + f'''-)
  EXPECT_GT(derivativeNoise(cubic, 1.0, 2, 0.1), 0.0);
}

}  // namespace
}  // namespace fsdb::testing
