#pragma once
// AffineForm: affine arithmetic (J. Stolfi and L. H. de Figueiredo, "Self-validated numerical
// methods and applications", 1997, §3) over a fixed set of noise symbols.
//
// A form x̂ = x0 + Σ_i x_i·ε_i + e·ε_* stands for every value it can take with each noise symbol ε_i
// in [−1, 1] and the accumulated error ε_* in [−1, 1]. Inputs that depend on the same ε_i (the
// fuzzy values of a part and the point coordinates) keep that correlation through the operations,
// so x − x is 0 and the range of an affine function of the inputs is exact; interval arithmetic
// (interval.h) would treat each occurrence as independent. This is what makes enclosures of a
// long chain of maps (the inverse deformations) over a box of 14 parameters tight where a first
// order interval or mean-value enclosure is several times too wide.
//
// Contract:
//  * Soundness: if every input's true value lies in its form, so does the result's, for every
//    assignment of the ε_i (the same ε_i for every form). The accumulated error e is treated as a
//    fresh independent symbol every time (the "AF1" variant of Messine): it never cancels, which
//    keeps soundness without allocating symbols. Each operation also adds a rounding slack of a few
//    ulps of the magnitudes involved to e, so results are sound under double rounding as well.
//  * Nonlinear functions use a second-order remainder about the centre x0:
//    f(x) = f(x0) + f'(x0)·(x − x0) + f''(ξ)/2·(x − x0)², with f'' enclosed over the form's range
//    (so the error shrinks quadratically with the box); atan uses the same rule.
//  * A form is `valid` unless an operation left its domain (log or sqrt of a range that reaches
//    0, a reciprocal of a range that holds 0, a non-finite value); invalid propagates, and callers
//    fall back to their interval enclosure. Invalid forms have no meaningful range.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/numeric/interval.h"

namespace fsdb {

// Noise symbols: the fourteen part values (slot order, superquadric_slopes.h), the three
// coordinates of a point box, and one spare, so that the loops over them vectorise in pairs.
inline constexpr int kAffineSymbols = 18;

struct AffineForm {
  double centre = 0.0;
  double dev[kAffineSymbols] = {};  // partial deviations x_i
  double err = 0.0;                 // radius of the accumulated error, >= 0
  bool valid = true;
};

AffineForm affineConstant(double c);
// The form of a value ranging over [range.lo, range.hi] with noise symbol `symbol` (0 <= symbol <
// kAffineSymbols): centre mid, deviation the half width.
AffineForm affineVariable(const Interval& range, int symbol);

// radius(x) = Σ|x_i| + e (the largest distance from the centre); range(x) = [x0 ∓ radius]
// (meaningful only when valid); add, sub, add(c, x), mul(c, x), combine (a·x + b·y (+ c·z)),
// mul(x, y) (the bilinear term
// bounded by rx·ry less what its diagonal ε_i² terms give back), sqr(x) ((x − x0)² in [0, r²]):
// inline, below (the enclosures call them in their innermost loops).

AffineForm recip(const AffineForm& x);  // 1/x; invalid if the range holds 0
AffineForm sqrt(const AffineForm& x);   // invalid unless the range is > 0
AffineForm exp(const AffineForm& x);    // invalid if the range exceeds 700 (overflow)
AffineForm log(const AffineForm& x);    // invalid unless the range is > 0
AffineForm sin(const AffineForm& x);
AffineForm cos(const AffineForm& x);
AffineForm atan(const AffineForm& x);
// x^q for a base whose range is > 0 (invalid otherwise, or where the result overflows): one
// second-order Taylor step in both arguments about the centres, with the Hessian of x^q
// (q(q−1)x^(q−2), x^(q−1)(1 + q·ln x), x^q·ln²x) enclosed over the box of the two ranges. One
// remainder instead of the three of exp(q·log x) (log, product, exp), so a power over a canonical
// ratio keeps several times less accumulated error.
AffineForm pow(const AffineForm& x, const AffineForm& q);
// |x|^q for any range of x (also one that reaches or straddles 0) and exponents q in an interval
// with q.lo >= 1, where |x|^q is convex in x: the Chebyshev band of a convex function, the secant
// slope s (at the mid exponent) kept as the correlation with x and [min, max] of |x|^q − s·x over
// the range and both exponent ends as the error (the minimum at the stationary point
// (|s|/q)^(1/(q−1)) with the sign of s, the maximum at an end). No correlation with q is kept.
// Near 0, where the direct rule's Hessian is unbounded, the band is several times narrower than
// the interval range (x^1.54 on [0, b]: about 0.16·b^1.54 against b^1.54). Invalid for q.lo < 1,
// non-finite input or overflow.
AffineForm absPow(const AffineForm& x, const Interval& q);

// A form with no correlation: the interval as centre and accumulated error (for quantities only
// an interval enclosure can bound; invalid for non-finite ends).
AffineForm affineFromInterval(const Interval& a);

// Inline: the enclosures call these in their innermost loops.
namespace affine_detail {
// Rounding slack per operation, relative to the magnitudes of the result's terms: each term is one
// or two roundings away from its exact value, and so is their sum in radius().
inline constexpr double kSlack = 4.0 * std::numeric_limits<double>::epsilon();

inline AffineForm invalid() {
  AffineForm r;
  r.valid = false;
  return r;
}

inline double deviationSum(const AffineForm& x) {
  double s = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) s += std::fabs(x.dev[i]);
  return s;
}

// Adds the rounding slack to a result whose deviations sum to d in magnitude, and checks it is
// finite and tame (kTame, interval.h: products of two tame forms stay finite, so no ∞·0 = NaN can
// hide in a deviation).
inline AffineForm finish(AffineForm r, double d) {
  if (!r.valid) return r;
  r.err += kSlack * (std::fabs(r.centre) + d + r.err);
  if (!(std::fabs(r.centre) <= kTame && d <= kTame && r.err <= kTame)) return invalid();
  return r;
}
inline AffineForm finish(const AffineForm& r) { return finish(r, deviationSum(r)); }

}  // namespace affine_detail

inline double radius(const AffineForm& x) { return affine_detail::deviationSum(x) + x.err; }

inline Interval range(const AffineForm& x) {
  const double r = radius(x);
  return {x.centre - r, x.centre + r};
}

inline AffineForm add(const AffineForm& x, const AffineForm& y) {
  AffineForm r;
  r.valid = x.valid && y.valid;
  r.centre = x.centre + y.centre;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = x.dev[i] + y.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = x.err + y.err;
  return affine_detail::finish(r, d);
}

inline AffineForm sub(const AffineForm& x, const AffineForm& y) {
  AffineForm r;
  r.valid = x.valid && y.valid;
  r.centre = x.centre - y.centre;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = x.dev[i] - y.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = x.err + y.err;
  return affine_detail::finish(r, d);
}

inline AffineForm add(double c, const AffineForm& x) {
  AffineForm r = x;
  r.centre += c;
  return affine_detail::finish(r);
}

inline AffineForm mul(double c, const AffineForm& x) {
  AffineForm r;
  r.valid = x.valid && std::isfinite(c);
  r.centre = c * x.centre;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = c * x.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = std::fabs(c) * x.err;
  return affine_detail::finish(r, d);
}

// a·x + b·y and a·x + b·y + c·z in one pass (linear maps, e.g. rotations, take one operation
// per coordinate instead of five).
inline AffineForm combine(double a, const AffineForm& x, double b, const AffineForm& y) {
  AffineForm r;
  r.valid = x.valid && y.valid && std::isfinite(a) && std::isfinite(b);
  r.centre = a * x.centre + b * y.centre;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = a * x.dev[i] + b * y.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = std::fabs(a) * x.err + std::fabs(b) * y.err +
          affine_detail::kSlack * (std::fabs(a * x.centre) + std::fabs(b * y.centre));
  return affine_detail::finish(r, d);
}
inline AffineForm combine(double a, const AffineForm& x, double b, const AffineForm& y, double c,
                          const AffineForm& z) {
  AffineForm r;
  r.valid = x.valid && y.valid && z.valid && std::isfinite(a) && std::isfinite(b) &&
            std::isfinite(c);
  r.centre = a * x.centre + b * y.centre + c * z.centre;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = a * x.dev[i] + b * y.dev[i] + c * z.dev[i];
    d += std::fabs(r.dev[i]);
  }
  r.err = std::fabs(a) * x.err + std::fabs(b) * y.err + std::fabs(c) * z.err +
          affine_detail::kSlack *
              (std::fabs(a * x.centre) + std::fabs(b * y.centre) + std::fabs(c * z.centre));
  return affine_detail::finish(r, d);
}

// (x0 + δx)(y0 + δy) = x0·y0 + x0·δy + y0·δx + δx·δy, |δx·δy| <= rx·ry.
inline AffineForm mul(const AffineForm& x, const AffineForm& y) {
  AffineForm r;
  r.valid = x.valid && y.valid;
  double d = 0.0, dx = 0.0, dy = 0.0, pos = 0.0, neg = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    r.dev[i] = x.centre * y.dev[i] + y.centre * x.dev[i];
    d += std::fabs(r.dev[i]);
    dx += std::fabs(x.dev[i]);
    dy += std::fabs(y.dev[i]);
    const double p = x.dev[i] * y.dev[i];
    pos += std::max(p, 0.0);
    neg += std::min(p, 0.0);
  }
  // δx·δy = Σ_i x_i·y_i·ε_i² + Σ_{i≠j} x_i·y_j·ε_i·ε_j (+ the error terms): the squares lie in
  // [0, 1], so the diagonal lies in [neg, pos]; the rest is bounded by rx·ry − Σ|x_i·y_i|.
  const double diagonal = pos - neg;  // Σ|x_i·y_i|
  r.centre = x.centre * y.centre + 0.5 * (pos + neg);
  r.err = std::fabs(x.centre) * y.err + std::fabs(y.centre) * x.err +
          std::max((dx + x.err) * (dy + y.err) - diagonal, 0.0) + 0.5 * diagonal;
  return affine_detail::finish(r, d);
}

// (x0 + δ)² = x0² + 2·x0·δ + δ², δ² in [0, r²].
inline AffineForm sqr(const AffineForm& x) {
  const double r = radius(x);
  AffineForm y;
  y.valid = x.valid;
  y.centre = x.centre * x.centre + 0.5 * r * r;
  double d = 0.0;
  for (int i = 0; i < kAffineSymbols; ++i) {
    y.dev[i] = 2.0 * x.centre * x.dev[i];
    d += std::fabs(y.dev[i]);
  }
  y.err = 2.0 * std::fabs(x.centre) * x.err + 0.5 * r * r;
  return affine_detail::finish(y, d);
}

}  // namespace fsdb
