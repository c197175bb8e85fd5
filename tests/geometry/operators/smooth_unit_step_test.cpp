// SmoothUnitStep: each family evaluates its step function with the rising range of Li,
// Def. 3 (Li & Tian, eq. 3, for polynomialRange), and the factories validate.
#include "tests/geometry/expect_error.h"
#include "geometry/operators/smooth_unit_step.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "geometry/operators/step_functions.h"

namespace fsdb {
namespace {

TEST(SmoothUnitStep, EachFamilyIsItsFunctionWithRisingRange) {
  for (double t = -3.0; t <= 3.0; t += 0.0625) {
    EXPECT_EQ(SmoothUnitStep::polynomial(4, 2.0)(t), polynomialStep(4, t / 2.0));
    EXPECT_EQ(SmoothUnitStep::polynomialRange(4, 2.0)(t), liTianStepRange(4, 2.0, t));
    EXPECT_EQ(SmoothUnitStep::bspline(5, 0.5)(t), bsplineStep(5, t / 0.5));
    EXPECT_EQ(SmoothUnitStep::risingCutoff(2, 0.5)(t), risingCutoff(2, t / 0.5));
    EXPECT_EQ(SmoothUnitStep::risingCutoffSquared(2, 0.5)(t), risingCutoffSquared(2, t / 0.5));
    EXPECT_EQ(SmoothUnitStep::sigmoid(6.0, 0.25)(t), sigmoidStep(6.0, t / 0.25));
    // Li & Tian's H_{n,R} and Li's H_n with epsilon = R are one function
    EXPECT_NEAR(SmoothUnitStep::polynomialRange(3, 0.7)(t), SmoothUnitStep::polynomial(3, 0.7)(t),
                1e-15);
  }
}

TEST(SmoothUnitStep, DefaultRangeIsOneAndAccessorsReport) {
  SmoothUnitStep s = SmoothUnitStep::bspline(3);
  EXPECT_EQ(s.family(), StepFamily::kBSpline);
  EXPECT_EQ(s.degree(), 3);
  EXPECT_EQ(s.risingRange(), 1.0);
  SmoothUnitStep g = SmoothUnitStep::sigmoid(7.0, 0.5);
  EXPECT_EQ(g.family(), StepFamily::kSigmoid);
  EXPECT_EQ(g.alpha(), 7.0);
  EXPECT_EQ(g.risingRange(), 0.5);
  EXPECT_EQ(SmoothUnitStep::polynomial(3)(1.0), 1.0);
  EXPECT_EQ(SmoothUnitStep::polynomial(3)(-1.0), 0.0);
}

TEST(SmoothUnitStep, FactoriesRejectBadParameters) {
  expectInvalidParameter([] { SmoothUnitStep::polynomial(0); }, "n");
  expectInvalidParameter([] { SmoothUnitStep::polynomial(3, 0.0); }, "epsilon");
  expectInvalidParameter([] { SmoothUnitStep::polynomialRange(3, -1.0); }, "R");
  expectInvalidParameter([] { SmoothUnitStep::bspline(kMaxBSplineOrder + 1); }, "m");
  expectInvalidParameter([] { SmoothUnitStep::risingCutoff(0); }, "n");
  expectInvalidParameter([] { SmoothUnitStep::risingCutoffSquared(3, -2.0); }, "epsilon");
  expectInvalidParameter([] { SmoothUnitStep::sigmoid(0.0); }, "alpha");
  expectInvalidParameter([] { SmoothUnitStep::sigmoid(1.0, 0.0); }, "epsilon");
}

}  // namespace
}  // namespace fsdb
