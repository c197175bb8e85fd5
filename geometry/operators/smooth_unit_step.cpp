#include "geometry/operators/smooth_unit_step.h"

#include <limits>

#include "geometry/core/parameter_check.h"
#include "geometry/operators/step_functions.h"

namespace fsdb {

namespace {

double checkedRange(const char* name, double epsilon) {
  requireInRange(name, epsilon, 0.0, false, std::numeric_limits<double>::infinity(), false);
  return epsilon;
}

}  // namespace

SmoothUnitStep SmoothUnitStep::polynomial(int n, double epsilon) {
  requireDegree("n", n, 1, kMaxPolynomialStepDegree);
  return SmoothUnitStep(StepFamily::kPolynomial, n, 0.0, checkedRange("epsilon", epsilon));
}

SmoothUnitStep SmoothUnitStep::polynomialRange(int n, double R) {
  requireDegree("n", n, 1, kMaxPolynomialStepDegree);
  return SmoothUnitStep(StepFamily::kPolynomialRange, n, 0.0, checkedRange("R", R));
}

SmoothUnitStep SmoothUnitStep::bspline(int m, double epsilon) {
  requireDegree("m", m, 1, kMaxBSplineOrder);
  return SmoothUnitStep(StepFamily::kBSpline, m, 0.0, checkedRange("epsilon", epsilon));
}

SmoothUnitStep SmoothUnitStep::risingCutoff(int n, double epsilon) {
  requireDegree("n", n, 1, kMaxRisingCutoffLevel);
  return SmoothUnitStep(StepFamily::kRisingCutoff, n, 0.0, checkedRange("epsilon", epsilon));
}

SmoothUnitStep SmoothUnitStep::risingCutoffSquared(int n, double epsilon) {
  requireDegree("n", n, 1, kMaxRisingCutoffLevel);
  return SmoothUnitStep(StepFamily::kRisingCutoffSquared, n, 0.0, checkedRange("epsilon", epsilon));
}

SmoothUnitStep SmoothUnitStep::sigmoid(double alpha, double epsilon) {
  checkedRange("alpha", alpha);
  return SmoothUnitStep(StepFamily::kSigmoid, 0, alpha, checkedRange("epsilon", epsilon));
}

// Li, Def. 3: mu_epsilon(t) = mu(t / epsilon); Li & Tian, eq. 3, for polynomialRange.
double SmoothUnitStep::operator()(double t) const {
  switch (family_) {
    case StepFamily::kPolynomial: return fsdb::polynomialStep(degree_, t / epsilon_);
    case StepFamily::kPolynomialRange: return fsdb::liTianStepRange(degree_, epsilon_, t);
    case StepFamily::kBSpline: return fsdb::bsplineStep(degree_, t / epsilon_);
    case StepFamily::kRisingCutoff: return fsdb::risingCutoff(degree_, t / epsilon_);
    case StepFamily::kRisingCutoffSquared: return fsdb::risingCutoffSquared(degree_, t / epsilon_);
    case StepFamily::kSigmoid: return fsdb::sigmoidStep(alpha_, t / epsilon_);
  }
  return 0.0;  // unreachable: every family is handled above
}

}  // namespace fsdb
