#include "geometry/numeric/affine_form.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/numeric/interval_functions.h"

namespace fsdb {

namespace {

using affine_detail::finish;
using affine_detail::invalid;
using affine_detail::kSlack;

// A linear approximation of f over the range of x: f(x) ∈ slope·x + shift ± error.
struct Linear {
  double slope, shift, error;
};

// slope·x + shift ± error as a form (one pass over the deviations).
AffineForm apply(const AffineForm& x, const Linear& l) {
  if (!(std::isfinite(l.slope) && std::isfinite(l.shift) && std::isfinite(l.error)))
    return invalid();
  AffineForm y;
  y.centre = l.slope * x.centre + l.shift;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    y.dev[i] = l.slope * x.dev[i];
    d += std::fabs(y.dev[i]);
  }
  // slope·x0 + shift may cancel: its rounding is relative to slope·x0, not to the result.
  y.err = std::fabs(l.slope) * x.err + l.error + kSlack * std::fabs(l.slope * x.centre);
  return finish(y, d);
}

// f(x) = f(x0) + f'(x0)·δ + f''(ξ)/2·δ² with δ = x − x0 in [−r, r] and f''(ξ) in s (an enclosure
// of f'' over the range of x): the remainder lies in [min(0, s.lo), max(0, s.hi)]·r²/2.
Linear secondOrder(double x0, double r, double f0, double d0, const Interval& s) {
  const double q = 0.5 * r * r;
  const double lo = std::min(0.0, s.lo) * q, hi = std::max(0.0, s.hi) * q;
  return {d0, f0 - d0 * x0 + 0.5 * (lo + hi), 0.5 * (hi - lo)};
}

// The min-range approximation (Stolfi & de Figueiredo §3.3) of an f that is monotone and convex or
// concave on the range [a, b] of x: the slope s = f' at the end where |f'| is least, so that
// f(x) − s·x is monotone and its range is its values at a and b (fa = f(a), fb = f(b)). Never
// wider than f's range, whatever f'' does on it (the second-order rule is tighter on narrow ones).
Linear minRange(const Interval& a, double s, double fa, double fb) {
  const double ga = fa - s * a.lo, gb = fb - s * a.hi;
  return {s, 0.5 * (ga + gb),
          0.5 * std::fabs(ga - gb) +
              kSlack * (std::fabs(fa) + std::fabs(fb) + std::fabs(s * a.lo) + std::fabs(s * a.hi))};
}

// The narrower of two approximations over a form whose deviations and error sum to r.
const Linear& narrower(const Linear& a, const Linear& b, double r) {
  const double wa = std::fabs(a.slope) * r + a.error, wb = std::fabs(b.slope) * r + b.error;
  if (!(wb < wa)) return std::isfinite(wa) ? a : b;
  return b;
}

// The validity checks every unary function starts with: the range [c − r, c + r].
bool rangeOf(const AffineForm& x, Interval* a, double* r) {
  if (!x.valid) return false;
  *r = radius(x);
  *a = {x.centre - *r, x.centre + *r};
  return std::isfinite(a->lo) && std::isfinite(a->hi);
}

}  // namespace

AffineForm affineConstant(double c) {
  AffineForm r;
  r.centre = c;
  if (!std::isfinite(c)) r.valid = false;
  return r;
}

AffineForm affineVariable(const Interval& a, int symbol) {
  AffineForm r;
  r.centre = mid(a);
  r.dev[symbol] = 0.5 * a.hi - 0.5 * a.lo;
  // mid and the half width round: keep both ends inside.
  r.err = kSlack * (std::fabs(r.centre) + r.dev[symbol]);
  if (!(std::isfinite(a.lo) && std::isfinite(a.hi))) r.valid = false;
  return r;
}

AffineForm affineFromInterval(const Interval& a) {
  AffineForm r;
  r.centre = mid(a);
  r.err = 0.5 * a.hi - 0.5 * a.lo;
  if (!(std::isfinite(a.lo) && std::isfinite(a.hi))) return invalid();
  return finish(r);
}

AffineForm recip(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r) || (a.lo <= 0.0 && a.hi >= 0.0)) return invalid();
  // (1/x)'' = 2/x³ decreases on each branch; |(1/x)'| = 1/x² is least at the end farthest from 0.
  const double c = x.centre, far = a.lo > 0.0 ? a.hi : a.lo;
  return apply(x, narrower(secondOrder(c, r, 1.0 / c, -1.0 / (c * c),
                                       {2.0 / (a.hi * a.hi * a.hi), 2.0 / (a.lo * a.lo * a.lo)}),
                           minRange(a, -1.0 / (far * far), 1.0 / a.lo, 1.0 / a.hi), r));
}

AffineForm sqrt(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r) || !(a.lo > 0.0)) return invalid();
  // (√x)'' = −x^(−3/2)/4 increases.
  const double s = std::sqrt(x.centre), sa = std::sqrt(a.lo), sb = std::sqrt(a.hi);
  return apply(x, narrower(secondOrder(x.centre, r, s, 0.5 / s, {-0.25 / (a.lo * sa), -0.25 / (a.hi * sb)}),
                           minRange(a, 0.5 / sb, sa, sb), r));
}

AffineForm exp(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r) || !(a.hi <= 700.0)) return invalid();
  const double e = std::exp(x.centre), ea = std::exp(a.lo), eb = std::exp(a.hi);
  return apply(x, narrower(secondOrder(x.centre, r, e, e, {ea, eb}), minRange(a, ea, ea, eb), r));
}

AffineForm log(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r) || !(a.lo > 0.0)) return invalid();
  // (log x)'' = −1/x² increases.
  const double c = x.centre;
  return apply(x, narrower(secondOrder(c, r, std::log(c), 1.0 / c, {-1.0 / (a.lo * a.lo), -1.0 / (a.hi * a.hi)}),
                           minRange(a, 1.0 / a.hi, std::log(a.lo), std::log(a.hi)), r));
}

AffineForm sin(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r)) return invalid();
  const double c = x.centre;
  return apply(x, secondOrder(c, r, std::sin(c), std::cos(c), neg(fsdb::sin(a))));
}

AffineForm cos(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r)) return invalid();
  const double c = x.centre;
  return apply(x, secondOrder(c, r, std::cos(c), -std::sin(c), neg(fsdb::cos(a))));
}

AffineForm atan(const AffineForm& x) {
  Interval a;
  double r;
  if (!rangeOf(x, &a, &r)) return invalid();
  // atan'' = −2x/(1 + x²)²: |atan''| <= 2|x|/(1 + x²)² <= 2·|x|max/(1 + |x|min²)², and never more
  // than its maximum 3√3/8 (at x = ±1/√3); its sign is that of −x.
  const double m = mignitude(a), d = (1.0 + m * m) * (1.0 + m * m);
  constexpr double kMax = 0.6495190528383291;  // 3√3/8, rounded up
  const double down = std::min(2.0 * std::max(a.hi, 0.0) / d, kMax);
  const double up = std::min(2.0 * std::max(-a.lo, 0.0) / d, kMax);
  const double c = x.centre;
  return apply(x, secondOrder(c, r, std::atan(c), 1.0 / (1.0 + c * c), {-down, up}));
}

AffineForm pow(const AffineForm& x, const AffineForm& q) {
  Interval a, b;
  double rx, rq;
  if (!rangeOf(x, &a, &rx) || !rangeOf(q, &b, &rq) || !(a.lo > 0.0)) return invalid();
  const double x0 = x.centre, q0 = q.centre, f0 = std::pow(x0, q0), l0 = std::log(x0);
  const double fx = q0 * f0 / x0, fq = f0 * l0;  // the gradient at the centre
  // The Hessian over the box: x^e = exp(e·ln x) for any real e, ln x in [ln a.lo, ln a.hi].
  const Interval lnx{std::log(a.lo), std::log(a.hi)};
  const auto powerOf = [&](double shift) {  // {x^(q − shift)}
    const Interval e = mul(Interval{b.lo - shift, b.hi - shift}, lnx);
    return Interval{std::exp(e.lo), std::exp(e.hi)};
  };
  const Interval hxx = mul(mul(b, Interval{b.lo - 1.0, b.hi - 1.0}), powerOf(2.0));
  const Interval hxq = mul(powerOf(1.0), add(Interval{1.0, 1.0}, mul(b, lnx)));
  const Interval hqq = mul(powerOf(0.0), sqr(lnx));
  // Lagrange remainder on the segment from the centre (it stays in the box): ½·δᵀHδ with
  // δx² in [0, rx²], δx·δq in [−rx·rq, rx·rq], δq² in [0, rq²]; its midpoint moves the centre.
  const double mixed = rx * rq;
  const Interval quadratic =
      mul(0.5, add(add(mul(hxx, Interval{0.0, rx * rx}), mul(2.0, mul(hxq, Interval{-mixed, mixed}))),
                   mul(hqq, Interval{0.0, rq * rq})));
  const double remainder = 0.5 * quadratic.hi - 0.5 * quadratic.lo;
  AffineForm r;
  r.centre = f0 + mid(quadratic);
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = fx * x.dev[i] + fq * q.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = std::fabs(fx) * x.err + std::fabs(fq) * q.err + remainder;
  if (!(std::isfinite(f0) && std::isfinite(fx) && std::isfinite(fq) && std::isfinite(remainder)))
    return invalid();
  return finish(r, d);
}

AffineForm absPow(const AffineForm& x, const Interval& q) {
  Interval a;
  double rx;
  if (!rangeOf(x, &a, &rx) || !(q.lo >= 1.0) || !std::isfinite(q.hi)) return invalid();
  const double qm = mid(q);
  const double fa = std::pow(std::fabs(a.lo), qm), fb = std::pow(std::fabs(a.hi), qm);
  const double s = a.hi > a.lo ? (fb - fa) / (a.hi - a.lo) : 0.0;
  // g(x) = |x|^e − s·x is convex for every exponent e >= 1; for a fixed x, |x|^e is monotone in e,
  // so the extremes over the box are at e = q.lo or q.hi: max at an end of the range, min at g's
  // stationary point (or an end, or 0 where the slope jumps for e = 1).
  const auto g = [&](double v, double e) { return std::pow(std::fabs(v), e) - s * v; };
  double up = -std::numeric_limits<double>::infinity(), lo = std::numeric_limits<double>::infinity();
  double magnitude = 0.0;
  for (double e : {q.lo, q.hi}) {
    for (double v : {a.lo, a.hi}) {
      const double gv = g(v, e);
      up = std::max(up, gv);
      lo = std::min(lo, gv);
      magnitude = std::max(magnitude, std::pow(std::fabs(v), e) + std::fabs(s * v));
    }
    lo = std::min(lo, g(std::min(std::max(0.0, a.lo), a.hi), e));
    if (e > 1.0 && s != 0.0) {
      const double stationary = std::copysign(std::pow(std::fabs(s) / e, 1.0 / (e - 1.0)), s);
      lo = std::min(lo, g(std::min(std::max(stationary, a.lo), a.hi), e));
    }
  }
  if (!(std::isfinite(up) && std::isfinite(lo) && std::isfinite(s))) return invalid();
  // The stationary point and the powers round: a relative slack of the magnitudes involved keeps
  // the band's ends outside g's true extremes.
  const double slack = 1e-12 * magnitude;
  lo -= slack;
  up += slack;
  return apply(x, {s, 0.5 * (lo + up), 0.5 * (up - lo)});
}

}  // namespace fsdb
