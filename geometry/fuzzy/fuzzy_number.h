#pragma once
// FuzzyNumber: a normal fuzzy set on the reals with a piecewise-linear membership function and
// bounded support, the value type of every fuzzy parameter (Zhang, Pham & Chen, §2.1: superquadric
// parameters, distances, angles; Sarwar & Akram: fuzzy control points).
//
// Representation: breakpoints (see geometry/numeric/piecewise_linear.h) with x non-decreasing, mu in
// [0, 1] and max mu == 1. Several breakpoints may share an x (a vertical jump): crisp numbers
// and trapezoids with vertical sides need them. The value at a jump is the larger side, so
// every alpha-cut is closed.
//
// Canonical form: every factory returns the breakpoints in one canonical form, so two numbers
// with the same membership function compare equal (operator==) and serialise alike:
//   - the list starts and ends at mu = 0 (an end with mu > 0 gets a vertical jump from 0);
//   - leading / trailing runs of mu = 0 are trimmed, so support() is [x_front, x_back];
//   - breakpoints sharing an x keep only (left limit, value, right limit), without repeats;
//   - interior breakpoints collinear with their neighbours (within 1e-12 in mu) are dropped.
//   So crisp(x) = [(x,0), (x,1), (x,0)], triangular(l,m,r) = [(l,0), (m,1), (r,0)],
//   trapezoidal(a,b,c,d) = [(a,0), (b,1), (c,1), (d,0)] (b == c gives the triangle).
//
// Non-convex memberships (more than one hump) are allowed. Their alpha-cut is not an interval;
// alphaCut(), strongAlphaCut(), support() and core() return its hull (the smallest interval
// holding it), which is the cut of the convex hull (quasi-concave envelope) of the membership.
//
// Errors: factories throw fsdb::Error with code errc::kInvalidDocument. The path names the bad
// argument inside the array form of the input ("[1]" for m of triangular(l, m, r), "[3][1]"
// for mu of the fourth point, "" for the whole), so a parser prefixes it with the JSON path of
// the array ("params.eps2.tri" + "[1]"). Queries given an alpha outside their range throw
// errc::kInvalidParameter with path "alpha".
#include <vector>

#include "geometry/numeric/interval.h"
#include "geometry/numeric/piecewise_linear.h"

namespace fsdb {

class FuzzyNumber {
 public:
  // crisp(0): a default value for containers and structs.
  FuzzyNumber();

  static FuzzyNumber crisp(double x);
  // mu rises linearly from l to m and falls from m to r; requires l <= m <= r.
  static FuzzyNumber triangular(double l, double m, double r);
  // mu rises on [a, b], is 1 on [b, c], falls on [c, d]; requires a <= b <= c <= d.
  static FuzzyNumber trapezoidal(double a, double b, double c, double d);
  // Any piecewise-linear normal membership: x finite and non-decreasing, mu in [0, 1], some
  // mu == 1. Ends with mu > 0 become vertical sides.
  static FuzzyNumber fromPoints(const std::vector<Breakpoint>& points);
  // The fuzzy number whose alpha-cut at alphas[k] is cuts[k] (the representation theorem),
  // its sides linear in alpha between the given levels. alphas: non-decreasing in [0, 1],
  // ending at 1; a level may appear twice, then the second cut is the strong cut there
  // (strongAlphaCut: a horizontal piece of mu at that height). cuts: nested (lo
  // non-decreasing, hi non-increasing, lo <= hi); violations up to 1e-9 of the magnitude
  // (rounding) are clamped. Below alphas[0] the cut stays cuts[0] (vertical sides from 0).
  // Errors: errc::kInvalidParameter, path "alphas[k]" or "cuts[k]". Fuzzy arithmetic builds
  // its results with it; fuzzy volumes (per-level [lower, upper] volumes) can too.
  static FuzzyNumber fromAlphaCuts(const std::vector<double>& alphas,
                                   const std::vector<Interval>& cuts);

  // mu(x); at a vertical jump the larger side; 0 outside the support (and for NaN).
  double membership(double x) const;
  // Hull of {x : mu(x) >= alpha} for alpha in (0, 1]; alpha == 0 gives the support's closure.
  Interval alphaCut(double alpha) const;
  // Hull of the closure of {x : mu(x) > alpha} for alpha in [0, 1): the limit of alphaCut(t)
  // as t decreases to alpha. It differs from alphaCut(alpha) only where mu has a horizontal
  // piece at height alpha; exact fuzzy arithmetic needs both.
  Interval strongAlphaCut(double alpha) const;
  Interval support() const;  // [x_front, x_back]
  Interval core() const;     // alphaCut(1)
  bool isCrisp() const;      // support is a single point
  bool isConvex() const;     // mu rises, then falls (every alpha-cut is an interval)
  double cardinality() const;  // exact area under mu (0 for a crisp number)
  const std::vector<Breakpoint>& breakpoints() const { return points_; }

 private:
  explicit FuzzyNumber(std::vector<Breakpoint> canonical) : points_(std::move(canonical)) {}

  std::vector<Breakpoint> points_;
};

// Same membership function (canonical breakpoints compare exactly).
bool operator==(const FuzzyNumber& a, const FuzzyNumber& b);
bool operator!=(const FuzzyNumber& a, const FuzzyNumber& b);

}  // namespace fsdb
