#pragma once
// Elementary functions of intervals: the enclosures the voxel evaluator needs to bound a
// superquadric's inside-outside function over a box of points and parameters
// (superquadric_bounds.h). Each returns the range {f(x) : x in a} (or of f(x, y)), computed
// from monotone pieces and the known extrema of the function, so it is tight up to rounding.
//
// Contract:
//  * Inputs are well-formed (lo <= hi, no NaN). Unless stated, ends may be infinite only where
//    the function's one-argument double version accepts them.
//  * No outward rounding: the ends are the double results of the end-point evaluations, so a
//    true value may lie a few ulps outside. Callers compare with a tolerance (the classifier
//    decides "inside" against F <= 1 with margins far above an ulp), which is why this is
//    enough and costs nothing.
//  * Results that would overflow saturate at the largest finite double where stated, as the
//    crisp inside-outside function does (superquadric.h).
#include <algorithm>
#include <cmath>

#include "geometry/numeric/interval.h"

namespace fsdb {

// Inline: the enclosures call these in their innermost loops.
inline Interval mul(double c, const Interval& a) {  // {c·x}
  return c >= 0.0 ? Interval{c * a.lo, c * a.hi} : Interval{c * a.hi, c * a.lo};
}
inline Interval neg(const Interval& a) { return {-a.hi, -a.lo}; }  // {−x}
// Halves first: no overflow. A point interval is its point (half of the smallest subnormal rounds
// to 0, so [5e-324, 5e-324] had the midpoint 0: found by fuzz_part_document).
inline double mid(const Interval& a) { return a.lo == a.hi ? a.lo : 0.5 * a.lo + 0.5 * a.hi; }
inline double magnitude(const Interval& a) {  // max |x| over a
  return std::max(std::fabs(a.lo), std::fabs(a.hi));
}
inline double mignitude(const Interval& a) {  // min |x| over a: 0 when a holds 0
  return a.lo > 0.0 ? a.lo : a.hi < 0.0 ? -a.hi : 0.0;
}
inline bool isPoint(const Interval& a, double v) { return a.lo == v && a.hi == v; }  // a == [v, v]

// The intersection of two enclosures of the same quantity. Both are sound, so the true value
// lies in both; if rounding makes them miss each other by an ulp, the gap between them is
// returned instead of an empty interval.
Interval intersect(const Interval& a, const Interval& b);

Interval abs(const Interval& a);   // {|x|}: [0, max] when a holds 0
Interval sqr(const Interval& a);   // {x²}, tight (not a·a, which gives [−1, 1]² = [−1, 1])
Interval sqrt(const Interval& a);  // precondition a.lo >= 0

// {x^e : x in base, e in exponent} for base.lo >= 0 and exponent.lo > 0. x^e increases in x;
// in e it increases where x >= 1 and decreases where x <= 1, so each end is one corner.
// Saturates at the largest finite double; 0^e = 0.
Interval pow(const Interval& base, const Interval& exponent);

// atan(w)/w, = 1 at w = 0 (the inverse bend's z = (Z/u)·atanc(kv·Z/u), deformation.cpp); the
// dropped series term w⁴/5 is < 2e-17 below |w| = 1e-4.
inline double atanc(double w) {
  if (std::fabs(w) < 1e-4) return 1.0 - w * w / 3.0;
  return std::atan(w) / w;
}
Interval atanc(const Interval& w);  // {atan(w)/w}: even and falling in |w|, so its ends
// {d/dw atanc(w)} = {(1/(1 + w²) − atanc(w))/w}: odd, with its extremes ∓0.29224806 at w = ±0.8243
// (falling between them, rising outside), so its range is at the ends and at ±0.8243 where held;
// near 0 by its series −2w/3 + 4w³/5 − 6w⁵/7 widened by the truncation bound (8/9)|w|⁷.
Interval atancSlope(const Interval& w);

Interval sin(const Interval& a);  // radians; [−1, 1] for width >= 2π or non-finite ends
Interval cos(const Interval& a);

// {hypot(x, y)}: increasing in |x| and |y|, so the ends are hypot of the |.| ends.
Interval hypot(const Interval& x, const Interval& y);

// {atan2(y, x)} in [−π, π]. Over a box that holds the origin or meets the branch cut (the
// half-line x < 0, y = 0, where atan2 jumps from π to −π) the answer is all of [−π, π];
// otherwise the angles of a box are an interval reached at its corners.
Interval atan2(const Interval& y, const Interval& x);

}  // namespace fsdb
