#pragma once
// Interval: a closed real interval [lo, hi] and its arithmetic (Moore's interval arithmetic).
//
// Contract: every function takes well-formed intervals (lo <= hi, finite) and returns the
// tightest interval that holds op(x, y) for all x in a, y in b. Fuzzy arithmetic applies these
// per alpha-cut (the extension principle for convex fuzzy numbers); the voxel evaluator reuses
// them to bound an inside-outside function over a box of parameters.
// Division by an interval that holds 0 has no bounded result: it throws fsdb::Error with code
// errc::kDomainError and path "divisor".

#include <algorithm>

namespace fsdb {

struct Interval {
  double lo;
  double hi;
};

bool operator==(const Interval& a, const Interval& b);
bool operator!=(const Interval& a, const Interval& b);

// Magnitude limit for the enclosures' intermediate values (superquadric_bounds.cpp,
// superquadric_slopes.cpp, and the affine forms of affine_form.h): products of two values below
// it stay finite, so no ∞·0 = NaN can arise inside the interval products (whose min/max would
// hide it).
inline constexpr double kTame = 1e150;
inline bool isTame(const Interval& a) { return a.lo >= -kTame && a.hi <= kTame; }  // false for NaN

// The elementary operations are inline: the enclosures and interval slopes of the voxel
// evaluator call them in their innermost loops.
inline Interval add(const Interval& a, const Interval& b) {  // [a.lo + b.lo, a.hi + b.hi]
  return {a.lo + b.lo, a.hi + b.hi};
}
inline Interval sub(const Interval& a, const Interval& b) {  // [a.lo - b.hi, a.hi - b.lo]
  return {a.lo - b.hi, a.hi - b.lo};
}
inline Interval mul(const Interval& a, const Interval& b) {  // hull of the four endpoint products
  // Zhang, Pham & Chen, eq. 4: the ends are the min / max of a o b over the end points (x*y is
  // bilinear).
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return {std::min(std::min(p1, p2), std::min(p3, p4)), std::max(std::max(p1, p2), std::max(p3, p4))};
}
Interval div(const Interval& a, const Interval& b);  // a * [1/b.hi, 1/b.lo]; throws if 0 in b
Interval min(const Interval& a, const Interval& b);  // {min(x, y)}: [min(lo), min(hi)]
Interval max(const Interval& a, const Interval& b);  // {max(x, y)}: [max(lo), max(hi)]

bool contains(const Interval& a, double x);             // a.lo <= x <= a.hi
bool contains(const Interval& outer, const Interval& inner);  // inner ⊆ outer
double width(const Interval& a);                        // a.hi - a.lo
Interval hull(const Interval& a, const Interval& b);    // smallest interval holding both

}  // namespace fsdb
