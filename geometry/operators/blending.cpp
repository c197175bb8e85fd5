#include "geometry/operators/blending.h"

#include <limits>

#include "geometry/core/parameter_check.h"

namespace fsdb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

SmoothUnitStep defaultBlendStep() { return SmoothUnitStep::polynomial(3); }

ExteriorBlend::ExteriorBlend(double delta, double epsilon, SmoothUnitStep mu)
    : delta_(delta), epsilon_(epsilon), mu_(mu) {
  requireInRange("delta", delta, 0.0, false, kInf, false);
  requireInRange("epsilon", epsilon, 0.0, false, kInf, false);
}

// Li, eq. 18-19 (the printed f(t) = x^2/(2 delta) + delta/2 means t^2/(2 delta) + delta/2:
// the parabola through (-delta, delta) and (delta, delta) with slopes -1 and 1 described after
// eq. 19).
double ExteriorBlend::sAbs(double t) const {
  double f = t * t / (2.0 * delta_) + delta_ / 2.0;
  double g1 = muEpsilon(t + delta_);
  double g2 = muEpsilon(t - delta_);
  return (g1 + g2 - 1.0) * t + g1 * (1.0 - g2) * f;
}

// Li, eq. 20
double ExteriorBlend::extMax(double x, double y) const { return (x + y + sAbs(x - y)) / 2.0; }

// Li, eq. 21
double ExteriorBlend::unionOf(double a, double b) const { return extMax(a, b); }

// Li, eq. 22
double ExteriorBlend::intersection(double a, double b) const { return -extMax(-a, -b); }

// Li, eq. 23
double ExteriorBlend::difference(double a, double b) const { return -extMax(-a, b); }

InteriorBlend::InteriorBlend(double epsilon, SmoothUnitStep mu) : epsilon_(epsilon), mu_(mu) {
  requireInRange("epsilon", epsilon, 0.0, false, kInf, false);
}

// Li, eq. 24
double InteriorBlend::intMax(double x, double y) const {
  double m = muEpsilon(y - x);
  return (1.0 - m) * x + m * y;
}

// Li, eq. 25
double InteriorBlend::unionOf(double a, double b) const { return intMax(a, b); }

// Li, eq. 26 (printed "-Int_max(x, y)(-F_A, -F_B, eps)": Int_max applied to -F_A, -F_B)
double InteriorBlend::intersection(double a, double b) const { return -intMax(-a, -b); }

// Li, eq. 27
double InteriorBlend::difference(double a, double b) const { return -intMax(-a, b); }

double sAbs(double t, double delta, double epsilon, const SmoothUnitStep& mu) {
  return ExteriorBlend(delta, epsilon, mu).sAbs(t);
}

double extMax(double x, double y, double delta, double epsilon, const SmoothUnitStep& mu) {
  return ExteriorBlend(delta, epsilon, mu).extMax(x, y);
}

double intMax(double x, double y, double epsilon, const SmoothUnitStep& mu) {
  return InteriorBlend(epsilon, mu).intMax(x, y);
}

}  // namespace fsdb
