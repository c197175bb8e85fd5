#pragma once
// Fuzzy Bézier curves and tensor-product surfaces (Sarwar & Akram): control points
// whose coordinates are fuzzy numbers, evaluated per alpha level by de Casteljau on the
// alpha-cuts, degree elevation, iso-parametric curves, fuzzy rational curves and
// defuzzification to crisp control points. Pure math, no I/O.
//
// Fuzzy control points (Sarwar & Akram, Def. 3): each coordinate is a FuzzyNumber; the paper's
// triangular (left, crisp, right) is FuzzyNumber::triangular(l, m, r), whose alpha-cut is
// [l + α(m − l), r − α(r − m)]. Every other form of geometry/fuzzy/fuzzy_number.h is accepted too
// (the cut is then FuzzyNumber::alphaCut, the hull for a non-convex number).
//
// Evaluation at level α (Sarwar & Akram, Algorithm 1, fuzzification eq. 3): the lower curve is de
// Casteljau on the lower ends of the control points' cuts, the upper curve on the upper ends,
// the crisp curve on the midpoints of the cores (for a triangular number: m). Because the
// Bernstein weights are non-negative and sum to one (Sarwar & Akram, §2, convex hull property),
// lower(u)[c] and upper(u)[c] are exactly the ends of the alpha-cut of coordinate c of the
// fuzzy point C(u) given by the extension principle, coordinate by coordinate: the point set of
// the curve at level α lies in the box [lower(u), upper(u)], and lower ≤ crisp ≤ upper.
// Surfaces (Sarwar & Akram, Algorithm 2): de Casteljau along each row of the grid at v, then along
// the resulting column at u, on the same three ends.
//
// Fuzzy rational curves (Sarwar & Akram, §2, FRB curve): C(u) = Σ B_k w_k P_k / Σ B_k w_k with
// fuzzy weights w_k (support strictly positive). The paper evaluates them through the homogeneous
// form (w P, w) and the projection Π; that is what the crisp curve does (core midpoints of
// weights and points). For lower / upper we return the interval hull, coordinate by
// coordinate, of C(u) over every choice of weights and points inside their alpha-cuts: the
// smallest box a designer can trust to hold every curve the fuzzy data allow. Projecting the
// cut ends of the homogeneous curve instead (Σ B lo(wP) / Σ B hi(w)) is also an enclosure but
// a loose one that does not reduce to the polynomial bounds when the weights are equal; the
// hull does. It is exact: for fixed weights C(u)[c] grows with each point coordinate, so its
// minimum takes the lower ends; over the weight box the weighted mean is smallest when the
// largest weights go to the smallest values, so the minimiser gives weight hi to the k smallest
// lower ends and lo to the rest for some k; all n + 1 splits are tried (the maximum likewise).
// With equal weights every split gives the polynomial curve.
//
// Degree elevation (Sarwar & Akram, "Degree elevation for a fuzzy B.B curve"): P'_k = k/(r+1)
// P_{k−1} + (1 − k/(r+1)) P_k on the fuzzy numbers (fuzzy_arithmetic.h add and scale: exact, since
// the coefficients are non-negative). The alpha-cut of the elevated point is the same combination
// of the cuts, so lower, crisp and upper curves are unchanged. Rational curves elevate in
// homogeneous form: with crisp weights the new points are again convex combinations of the old
// (coefficients a w_{k−1} / w'_k and (1 − a) w_k / w'_k), so the curve at every level is
// unchanged; fuzzy weights would need fuzzy division, whose dependency problem widens the cuts,
// so elevateCurve refuses them (errc::kInvalidParameter, path "weights").
//
// Defuzzification (Sarwar & Akram, eq. 4, after ref. [11]): each coordinate of each control point
// is replaced by a crisp value, using geometry/fuzzy/defuzzify.h. The default is the centroid,
// which for the paper's triangular (l, m, r) is (l + m + r) / 3, the average of left, crisp and
// right control points; the maxima and bisector defuzzifiers are available too. Weights of a
// rational curve are defuzzified by the same method.
//
// Errors (fsdb::Error): empty control polygons, ragged grids, points of different dimensions,
// a weight list of the wrong length and weights whose support reaches 0 or below are
// errc::kInvalidDocument with the path of the bad item ("control_points[2]", "weights[1]",
// "control_grid[1][3]"); α outside [0, 1] and u, v outside [0, 1] (or not finite) are
// errc::kInvalidParameter ("alpha", "u", "v"); a point whose values overflow the double range
// (coordinates or weights near ±1.8e308) is errc::kDomainError ("control_points", "control_grid"),
// so an evaluation never returns inf or NaN.
#include <cstddef>
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

using FuzzyPoint = std::vector<FuzzyNumber>;  // one fuzzy number per coordinate
using CrispPoint = std::vector<double>;

struct FuzzyBezierCurve {
  std::vector<FuzzyPoint> controlPoints;  // degree r = size − 1
  std::vector<FuzzyNumber> weights;       // empty: polynomial; else one per control point
  bool isRational() const { return !weights.empty(); }
  std::size_t degree() const { return controlPoints.empty() ? 0 : controlPoints.size() - 1; }
};

// controlGrid[i][j]: i along u (degree rows − 1), j along v (degree columns − 1);
// S(u, v) = Σ_i Σ_j B_i(u) B_j(v) P_ij (Sarwar & Akram, Def. 5).
struct FuzzyBezierSurface {
  std::vector<std::vector<FuzzyPoint>> controlGrid;
};

// The three curves (or surfaces) at one parameter and one level.
struct FuzzyBezierPoint {
  CrispPoint lower, crisp, upper;
};

enum class Defuzzifier { kCentroid, kBisector, kMeanOfMaxima, kSmallestOfMaxima, kLargestOfMaxima };

// Throw as the header says when the curve or surface is malformed (evaluation checks too).
void validateCurve(const FuzzyBezierCurve& curve);
void validateSurface(const FuzzyBezierSurface& surface);

// B_k^r(u) = C(r, k) u^k (1 − u)^(r − k) (Sarwar & Akram, Def. 4), the closed form (C(r, k)
// overflows beyond r ≈ 1000; the evaluators use bernsteinBasis).
double bernstein(std::size_t r, std::size_t k, double u);
// B_0^r(u) .. B_r^r(u) by the recurrence B_k^j = (1 − u) B_k^{j−1} + u B_{k−1}^{j−1}: no
// binomials, so no overflow at any degree.
std::vector<double> bernsteinBasis(std::size_t r, double u);
// Crisp de Casteljau (Sarwar & Akram, Algorithm 1 on one end): repeated linear interpolation.
CrispPoint deCasteljau(const std::vector<CrispPoint>& points, double u);

FuzzyBezierPoint evaluateCurve(const FuzzyBezierCurve& curve, double u, double alpha);
FuzzyBezierPoint evaluateSurface(const FuzzyBezierSurface& surface, double u, double v, double alpha);

// The same in two steps, for many parameters at one level: the cut ends of every control point
// (and weight) are computed once. evaluateCurve(c, u, a) == evaluateCut(cutCurve(c, a), u).
struct BezierCurveCut {
  std::size_t dimension = 0;
  std::vector<CrispPoint> ends;      // per control point: lower ends, core midpoints, upper ends
  std::vector<Interval> weights;     // rational only: the weights' cuts
  // Rational only, independent of u so built once per level: the homogeneous crisp points
  // (w P, w) from the core midpoints, and per coordinate the control points ordered by their
  // lower ends (order[c]) and by their upper ends descending (order[dimension + c]), the order
  // the hull's splits run in.
  std::vector<CrispPoint> homogeneous;
  std::vector<std::vector<std::size_t>> order;
};
struct BezierSurfaceCut {
  std::size_t dimension = 0;
  std::vector<std::vector<CrispPoint>> ends;  // as BezierCurveCut::ends, per grid point
};
BezierCurveCut cutCurve(const FuzzyBezierCurve& curve, double alpha);
BezierSurfaceCut cutSurface(const FuzzyBezierSurface& surface, double alpha);
FuzzyBezierPoint evaluateCut(const BezierCurveCut& cut, double u);
FuzzyBezierPoint evaluateCut(const BezierSurfaceCut& cut, double u, double v);

// The u iso-parametric curve S(·, v) and the v iso-parametric curve S(u, ·) as fuzzy Bézier
// curves (Sarwar & Akram, §2: control points Σ_j B_j(v) P_ij, fuzzy convex combinations).
FuzzyBezierCurve isoCurveU(const FuzzyBezierSurface& surface, double v);
FuzzyBezierCurve isoCurveV(const FuzzyBezierSurface& surface, double u);

// Degree r → r + times (times ≥ 0). Rational curves need crisp weights (see above).
FuzzyBezierCurve elevateCurve(const FuzzyBezierCurve& curve, int times);
// Elevates every row (v direction) timesV times and every column (u direction) timesU times.
FuzzyBezierSurface elevateSurface(const FuzzyBezierSurface& surface, int timesU, int timesV);

// Crisp control points (and weights, empty for a polynomial curve).
struct CrispBezierCurve {
  std::vector<CrispPoint> controlPoints;
  std::vector<double> weights;
};
double defuzzifyNumber(const FuzzyNumber& a, Defuzzifier method);
CrispPoint defuzzifyPoint(const FuzzyPoint& p, Defuzzifier method);
CrispBezierCurve defuzzifyCurve(const FuzzyBezierCurve& curve, Defuzzifier method);
std::vector<std::vector<CrispPoint>> defuzzifySurface(const FuzzyBezierSurface& surface, Defuzzifier method);

}  // namespace fsdb
