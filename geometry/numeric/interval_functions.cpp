#include "geometry/numeric/interval_functions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kMaxFinite = std::numeric_limits<double>::max();

// Does [lo, hi] hold a point phase + 2πn for some integer n? The smallest such point >= lo
// is phase + 2π·ceil((lo − phase)/2π).
bool holdsPhase(double lo, double hi, double phase) {
  const double n = std::ceil((lo - phase) / kTwoPi);
  return phase + n * kTwoPi <= hi;
}

// The range of a 2π-periodic function with one maximum (at maxPhase) and one minimum (at
// minPhase) per period, monotone between them: the end values, widened to ±1 where an
// extremum lies inside.
template <typename F>
Interval periodicRange(const Interval& a, F f, double maxPhase, double minPhase) {
  if (!(a.hi - a.lo < kTwoPi)) return {-1.0, 1.0};  // a whole period, or infinite/NaN ends
  const double fl = f(a.lo), fh = f(a.hi);
  Interval r{std::min(fl, fh), std::max(fl, fh)};
  if (holdsPhase(a.lo, a.hi, maxPhase)) r.hi = 1.0;
  if (holdsPhase(a.lo, a.hi, minPhase)) r.lo = -1.0;
  return r;
}

// The square, F's exponent for the common eps1 = 1, skips the general pow (as superquadric.cpp
// does); both round the same exact x² once.
double saturatedPow(double x, double e) {
  return std::min(e == 2.0 ? x * x : std::pow(x, e), kMaxFinite);
}

}  // namespace

Interval intersect(const Interval& a, const Interval& b) {
  const double lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
  return lo <= hi ? Interval{lo, hi} : Interval{hi, lo};
}

Interval abs(const Interval& a) {
  if (a.lo >= 0.0) return a;
  if (a.hi <= 0.0) return {-a.hi, -a.lo};
  return {0.0, std::max(-a.lo, a.hi)};
}

Interval sqr(const Interval& a) {
  const Interval m = abs(a);
  return {m.lo * m.lo, m.hi * m.hi};
}

// A lower end a rounding step below 0 (a sum of squares minus a cancellation) reads as 0.
Interval sqrt(const Interval& a) { return {std::sqrt(std::max(0.0, a.lo)), std::sqrt(a.hi)}; }

Interval pow(const Interval& base, const Interval& exponent) {
  // Smallest value: smallest base, with the exponent that shrinks it most (the largest one
  // below 1, the smallest one above 1); the largest value symmetrically.
  const double lo = saturatedPow(base.lo, base.lo >= 1.0 ? exponent.lo : exponent.hi);
  const double hi = saturatedPow(base.hi, base.hi >= 1.0 ? exponent.hi : exponent.lo);
  return {lo, hi};
}

Interval sin(const Interval& a) {
  return periodicRange(a, [](double x) { return std::sin(x); }, 0.5 * kPi, -0.5 * kPi);
}

Interval cos(const Interval& a) {
  return periodicRange(a, [](double x) { return std::cos(x); }, 0.0, kPi);
}

Interval hypot(const Interval& x, const Interval& y) {
  const Interval ax = abs(x), ay = abs(y);
  return {std::hypot(ax.lo, ay.lo), std::hypot(ax.hi, ay.hi)};
}

Interval atan2(const Interval& y, const Interval& x) {
  const bool meetsCut = x.lo < 0.0 && y.lo <= 0.0 && y.hi >= 0.0;  // also when it holds 0
  const bool holdsOrigin = contains(x, 0.0) && contains(y, 0.0);
  if (meetsCut || holdsOrigin) return {-kPi, kPi};
  // atan2 is continuous on the box, and the directions of a convex set that misses the
  // origin form an arc whose ends are directions of extreme points: corners here.
  const double c[4] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo),
                       std::atan2(y.hi, x.hi)};
  return {*std::min_element(c, c + 4), *std::max_element(c, c + 4)};
}

Interval atanc(const Interval& w) {
  return {atanc(magnitude(w)), atanc(mignitude(w))};
}

Interval atancSlope(const Interval& w) {
  const auto slope = [](double x) {
    if (std::fabs(x) < 0.05) {
      const double x2 = x * x;
      return x * (-2.0 / 3.0 + x2 * (4.0 / 5.0 - x2 * 6.0 / 7.0));
    }
    return (1.0 / (1.0 + x * x) - std::atan(x) / x) / x;
  };
  constexpr double kStar = 0.8243, kExtreme = 0.29224806 + 1e-8;
  double lo = std::min(slope(w.lo), slope(w.hi)), hi = std::max(slope(w.lo), slope(w.hi));
  if (w.lo <= kStar && kStar <= w.hi) lo = std::min(lo, -kExtreme);
  if (w.lo <= -kStar && -kStar <= w.hi) hi = std::max(hi, kExtreme);
  const double m = std::min(magnitude(w), 0.05);
  const double truncation = 8.0 / 9.0 * std::pow(m, 7.0) + 1e-15;
  return {lo - truncation, hi + truncation};
}

}  // namespace fsdb
