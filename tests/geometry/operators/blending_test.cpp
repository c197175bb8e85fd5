// Li, eq. 18-27: S_abs, Ext_max and Int_max with their unions, intersections and
// differences; the properties stated after eq. 19 and 23 and in §3.2, and smoothness.
#include "tests/geometry/expect_error.h"
#include "geometry/operators/blending.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/core/error.h"
#include "tests/geometry/smoothness.h"

namespace fsdb {
namespace {

std::vector<double> samples(double lo, double hi, int steps) {
  std::vector<double> s;
  for (int i = 0; i <= steps; ++i) s.push_back(lo + (hi - lo) * i / steps);
  return s;
}

// Steps with compact support [-1, 1] (the statements below need exact 0 and 1 outside).
std::vector<SmoothUnitStep> compactSteps() {
  return {SmoothUnitStep::polynomial(3),     SmoothUnitStep::polynomial(1),
          SmoothUnitStep::polynomial(6),     SmoothUnitStep::bspline(4),
          SmoothUnitStep::risingCutoff(2),   SmoothUnitStep::risingCutoffSquared(3),
          SmoothUnitStep::polynomialRange(2)};
}

TEST(Blending, DefaultStepIsTheCubicPolynomialStep) {
  SmoothUnitStep mu = defaultBlendStep();
  EXPECT_EQ(mu.family(), StepFamily::kPolynomial);
  EXPECT_EQ(mu.degree(), 3);
  EXPECT_EQ(mu.risingRange(), 1.0);
}

TEST(SAbs, IsAbsoluteOutsideAndTheParabolaInside) {
  for (const SmoothUnitStep& mu : compactSteps())
    for (double delta : {0.1, 0.5, 1.0, 5.0})
      for (double epsilon : {0.01, 0.25 * delta, 0.9 * delta}) {
        ExteriorBlend blend(delta, epsilon, mu);
        double outer = delta + epsilon, inner = delta - epsilon;
        for (double t : samples(-3 * outer, 3 * outer, 300)) {
          double s = blend.sAbs(t);
          if (std::fabs(t) > outer * (1 + 1e-12)) {
            EXPECT_EQ(s, std::fabs(t)) << delta << " " << epsilon << " " << t;
          }
          if (std::fabs(t) < inner * (1 - 1e-12)) {
            EXPECT_EQ(s, t * t / (2 * delta) + delta / 2) << delta << " " << epsilon << " " << t;
          }
          // For epsilon <= delta S_abs never falls below |t| (a convex mix of |t| and the
          // parabola, which lies above |t|).
          EXPECT_GE(s, std::fabs(t) - 1e-15) << delta << " " << epsilon << " " << t;
        }
      }
}

TEST(SAbs, TheParabolaMeetsAbsoluteWithMatchingSlopes) {
  // After eq. 19: f passes (-delta, delta), (delta, delta) with slopes -1 and 1.
  double delta = 0.7;
  ExteriorBlend blend(delta, 1e-3);
  auto f = [&](double t) { return t * t / (2 * delta) + delta / 2; };
  EXPECT_NEAR(f(delta), delta, 1e-15);
  EXPECT_NEAR(f(-delta), delta, 1e-15);
  EXPECT_NEAR((f(delta + 1e-6) - f(delta - 1e-6)) / 2e-6, 1.0, 1e-9);
  EXPECT_NEAR(blend.sAbs(0.0), delta / 2, 1e-15);
}

TEST(SAbs, IsEvenForAntisymmetricSteps) {
  for (const SmoothUnitStep& mu :
       {SmoothUnitStep::polynomial(3), SmoothUnitStep::bspline(5),
        SmoothUnitStep::risingCutoffSquared(2), SmoothUnitStep::sigmoid(4)}) {
    ExteriorBlend blend(0.5, 0.3, mu);
    for (double t : samples(0, 2, 50)) EXPECT_NEAR(blend.sAbs(t), blend.sAbs(-t), 1e-15);
  }
}

TEST(SAbs, FallsBelowAbsoluteWhenTheRisingRangeIsTooBig) {
  // "unless the rising range parameter is set too big": with epsilon = 4 delta the exterior
  // union no longer contains its operands somewhere.
  ExteriorBlend blend(0.25, 1.0);
  double worst = 0.0;
  for (double t : samples(-2, 2, 400)) worst = std::min(worst, blend.sAbs(t) - std::fabs(t));
  EXPECT_LT(worst, -0.01);
}

TEST(SAbs, IsC2WithTheCubicStep) {
  // Breakpoints of g1, g2 at t = +-delta +- epsilon and the inner knots +-delta +- epsilon/3.
  // At the inner knots the third-derivative jump is damped by t - f(t) = O(epsilon^2/delta),
  // so the differences need a fine h (pieces are 2 epsilon/3 wide; h = width/200).
  double delta = 1.0, epsilon = 0.25;
  ExteriorBlend blend(delta, epsilon);
  auto s = [&](double t) { return blend.sAbs(t); };
  double h = 2 * epsilon / 3 / 200;
  for (double b : {delta + epsilon, delta - epsilon, delta + epsilon / 3, delta - epsilon / 3,
                   -delta - epsilon, -delta + epsilon, -delta + epsilon / 3})
    EXPECT_TRUE(testing::exactlyCkAt(s, b, 2, h)) << b;
}

TEST(SAbs, IsC3WithTheDegree4Step) {
  // A C^(n-1) step gives a C^(n-1) blend (Li, §3.1, feature (3)). A wide rising range
  // keeps the fourth differences above rounding.
  double delta = 2.0, epsilon = 1.0;
  ExteriorBlend blend(delta, epsilon, SmoothUnitStep::polynomial(4));
  auto s = [&](double t) { return blend.sAbs(t); };
  for (double b : {delta + epsilon, delta - epsilon, -delta - epsilon, -delta + epsilon})
    EXPECT_TRUE(testing::exactlyCkAt(s, b, 3, 2 * epsilon / 4 / 40)) << b;
}

TEST(ExtMax, Eq20AndTheUnionContainsBothOperands) {
  for (const SmoothUnitStep& mu : compactSteps())
    for (double delta : {0.2, 1.0})
      for (double epsilon : {0.05, delta}) {
        ExteriorBlend blend(delta, epsilon, mu);
        for (double x : samples(-3, 3, 40))
          for (double y : samples(-3, 3, 40)) {
            double u = blend.extMax(x, y);
            EXPECT_DOUBLE_EQ(u, (x + y + blend.sAbs(x - y)) / 2);
            EXPECT_GE(u, std::max(x, y) - 1e-15);  // eq. 21 union contains A and B
            if (std::fabs(x - y) > (delta + epsilon) * (1 + 1e-12)) {
              EXPECT_NEAR(u, std::max(x, y), 1e-15);
            }
          }
      }
}

TEST(ExtMax, UnionIntersectionDifferenceAsPrinted) {
  ExteriorBlend blend(0.5, 0.25);
  for (double a : samples(-2, 2, 30))
    for (double b : samples(-2, 2, 30)) {
      EXPECT_EQ(blend.unionOf(a, b), blend.extMax(a, b));          // eq. 21
      EXPECT_EQ(blend.intersection(a, b), -blend.extMax(-a, -b));  // eq. 22
      EXPECT_EQ(blend.difference(a, b), -blend.extMax(-a, b));     // eq. 23
      // Dual containment: the intersection and the difference lie inside their crisp forms.
      EXPECT_LE(blend.intersection(a, b), std::min(a, b) + 1e-15);
      EXPECT_LE(blend.difference(a, b), std::min(a, -b) + 1e-15);
      EXPECT_NEAR(blend.unionOf(a, b), blend.unionOf(b, a), 1e-15);
    }
  // Two separated shapes are bridged: both outside (F < 0) yet the blended union is >= 0 where
  // |F_A - F_B| is small and delta is large (Li, Fig. 7).
  ExteriorBlend wide(6.0, 0.25);
  EXPECT_GT(wide.unionOf(-1.0, -1.0), 0.0);
  EXPECT_LT(ExteriorBlend(0.25, 0.05).unionOf(-1.0, -1.0), 0.0);
}

TEST(IntMax, Eq24StaysBetweenMinAndMax) {
  std::vector<SmoothUnitStep> steps = compactSteps();
  steps.push_back(SmoothUnitStep::sigmoid(3.0));
  for (const SmoothUnitStep& mu : steps)
    for (double epsilon : {0.05, 0.25, 5.0}) {
      InteriorBlend blend(epsilon, mu);
      for (double x : samples(-3, 3, 40))
        for (double y : samples(-3, 3, 40)) {
          double u = blend.intMax(x, y);
          double m = mu((y - x) / epsilon);
          EXPECT_DOUBLE_EQ(u, (1 - m) * x + m * y);
          EXPECT_GE(u, std::min(x, y) - 1e-15);  // eq. 25 union inside A u B...
          EXPECT_LE(u, std::max(x, y) + 1e-15);  // ...and never beyond
        }
    }
  InteriorBlend blend(0.25);
  EXPECT_EQ(blend.intMax(1.0, 0.5), 1.0);  // |x - y| >= epsilon: exactly max
  EXPECT_EQ(blend.intMax(0.5, 1.0), 1.0);
  EXPECT_EQ(blend.intMax(0.3, 0.3), 0.3);  // the joint lies on the blend (Li, §3.2)
}

TEST(IntMax, UnionIntersectionDifferenceAsPrinted) {
  InteriorBlend blend(0.5);
  for (double a : samples(-2, 2, 30))
    for (double b : samples(-2, 2, 30)) {
      EXPECT_EQ(blend.unionOf(a, b), blend.intMax(a, b));          // eq. 25
      EXPECT_EQ(blend.intersection(a, b), -blend.intMax(-a, -b));  // eq. 26
      EXPECT_EQ(blend.difference(a, b), -blend.intMax(-a, b));     // eq. 27
      // "the intersection ... always contains the intersection of the solids"
      EXPECT_GE(blend.intersection(a, b), std::min(a, b) - 1e-15);
      EXPECT_LE(blend.intersection(a, b), std::max(a, b) + 1e-15);
    }
}

TEST(IntMax, IsC2WithTheCubicStep) {
  double epsilon = 0.3;
  InteriorBlend blend(epsilon);
  auto along = [&](double y) { return blend.intMax(0.0, y); };  // y * mu(y / epsilon)
  double h = 2 * epsilon / 3 / 20;
  for (double b : {epsilon, -epsilon, epsilon / 3, -epsilon / 3})
    EXPECT_TRUE(testing::exactlyCkAt(along, b, 2, h)) << b;
}

TEST(Blending, OneShotFormsAndAccessors) {
  SmoothUnitStep mu = SmoothUnitStep::bspline(4);
  EXPECT_EQ(sAbs(0.3, 0.5, 0.2, mu), ExteriorBlend(0.5, 0.2, mu).sAbs(0.3));
  EXPECT_EQ(extMax(0.3, -0.1, 0.5, 0.2), ExteriorBlend(0.5, 0.2).extMax(0.3, -0.1));
  EXPECT_EQ(intMax(0.3, 0.1, 0.2, mu), InteriorBlend(0.2, mu).intMax(0.3, 0.1));
  EXPECT_EQ(ExteriorBlend(0.5, 0.2).delta(), 0.5);
  EXPECT_EQ(ExteriorBlend(0.5, 0.2).epsilon(), 0.2);
  EXPECT_EQ(InteriorBlend(0.7).epsilon(), 0.7);
}

TEST(Blending, ParametersOutsideRangeThrow) {
  expectInvalidParameter([] { ExteriorBlend(0.0, 0.1); }, "delta");
  expectInvalidParameter([] { ExteriorBlend(0.5, -0.1); }, "epsilon");
  expectInvalidParameter([] { InteriorBlend(0.0); }, "epsilon");
  expectInvalidParameter([] { sAbs(0.0, -1.0, 0.1); }, "delta");
  expectInvalidParameter([] { extMax(0.0, 0.0, 1.0, 0.0); }, "epsilon");
  expectInvalidParameter([] { intMax(0.0, 0.0, std::nan("")); }, "epsilon");
}

}  // namespace
}  // namespace fsdb
