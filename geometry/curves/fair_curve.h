#pragma once
// Fair plane curves from a pseudo-evolute (Bernardes, Wu & D'Ottaviano, §2): the curve
// C through points P_0..P_{N-1} is built piece by piece, C_k from P_k to P_{k+1} (and, closed,
// C_{N-1} from P_{N-1} back to P_0), as an evolvent (involute) of one cubic Bézier piece BP_k of
// the pseudo-evolute PE. Pure math; no I/O.
//
// Radii-vectors R_i (Bernardes, Wu & D'Ottaviano, §2, §4). Each point has a radius-vector: a
// direction (an angle in [0°, 180°) from the x axis; only the line matters, §4) and a magnitude.
// Choices where the text is vague, each checked by tests/geometry/curves/fair_curve_test.cpp:
//  - Magnitudes (§4 "only the relative magnitude matters"): relations[k] says whether P_{k+1}
//    (mod N) is SMOOTHER (larger radius) or SHARPER (smaller) than P_k. |R_i| = l * ratio^e_i with
//    e walking +1 / -1 per relation, l the mean chord length and ratio 1.5 by default. A closed
//    curve's walk must return to its start: the drift e_N / N is taken off every step, which keeps
//    every step's sign (so every relation holds) unless all relations are equal (then no
//    magnitudes can satisfy them: invalid_parameter, path "relations"). No relations: all equal.
//  - Orientation (the side of the centre of curvature): at an inner point R_i points to the
//    concave side of the polygon (dot(R_i, P_{i-1} + P_{i+1} - 2 P_i) > 0; at an open end, the
//    side of its chord); where that is 0 it keeps the side of a neighbour's R.
//  - First estimation (Figure 7 is "a first estimation"): the bisector of the angle at P_i
//    (direction of unit(P_{i-1} - P_i) + unit(P_{i+1} - P_i)); at an open end, the normal of the
//    end chord; straight through (no bisector), the normal of the next chord.
// The pseudo-evolute piece BP_k (§2): control points on the two radius-vector lines,
//   Q0 = P_k + d0 n_k, Q1 = P_k + d1 n_k, Q2 = P_{k+1} + d2 n_{k+1}, Q3 = P_{k+1} + d3 n_{k+1}
// (n = unit R; the text's B4, B3, B2, B1), the depths being Table 1's alpha_j |R| (0.25, 0.5 at
// each end) "chosen so that the convexity of the Bézier polygon is ensured". Taken literally,
// Table 1's depths give points on a circle a Z-shaped polygon and a looping curve, so:
//  - a convex piece (the radius lines cross at X on the concave side of both points) keeps Q1
//    short of X and Q2 beyond it (10% margins; d0 = d1 alpha_4/alpha_3, d3 = d2 + (alpha_1 -
//    alpha_2)|R|): the PE wraps round X and the piece of points on a circle is nearly circular;
//  - any other piece (an inflection, diverging lines) takes Table 1's depths, each end's pair
//    in the order under which the evolvent advances at both ends (see tablePolygon); when no
//    order does, Table 1's order as printed (the tangent may then reverse at a point: such
//    angles lie in danger zones; no candidate curve of the tests reaches this case).
// The signed string lengths s0, s1 (P = Q - s T at the ends, T the unit PE tangent) may differ
// in sign on an inflection piece: the curve then crosses its PE there, transversally.
// The evolvent (§2: "directions of the interpolated radii-vectors are given by the PE tangents,
// their magnitudes by linear interpolation"): C(t) = BP(t) - rho(t) T(t), T the unit PE tangent,
//   rho(t) = (1 - t) s0 + t s1 + h10(t) (|BP'(0)| - (s1 - s0)) + h11(t) (|BP'(1)| - (s1 - s0)),
// the paper's linear interpolation plus a cubic Hermite term (h10 = t^3 - 2t^2 + t,
// h11 = t^3 - t^2) that vanishes at both ends and gives rho' = |BP'| there, the exact involute's
// rate. So C(0) = P_k, C(1) = P_{k+1} exactly, and at both ends C' = -rho T' is perpendicular to
// the radius-vector line: both pieces meeting at P_i have the tangent normal to R_i (G1).
// Scale: every function takes and answers world coordinates but computes in the local frame of
// the points (plane_frame.h), so subnormal spacings and coordinates near the double range work.
// Errors: fsdb::Error(invalid_parameter) naming "points[i]" (non-finite, equal to the next point,
// or so close to it for the curve's size that their difference is lost), "points" (fewer than 2,
// closed fewer than 3; a curve that leaves the double range), "relations" (wrong count), "angles[i]".
#include <array>
#include <cstddef>
#include <vector>

#include "geometry/core/vec2.h"
#include "geometry/curves/plane_frame.h"

namespace fsdb {

enum class Relation { kSmoother, kSharper };

// Table 1 of Bernardes, Wu & D'Ottaviano: the alpha_j of every Bézier polygon.
struct EvoluteAlphas {
  double a1 = 0.5, a2 = 0.25, a3 = 0.5, a4 = 0.25;
};

struct FairCurve {
  std::vector<Vec2> points;  // P_i
  std::vector<Vec2> radii;   // R_i (oriented, with magnitude)
  bool closed = false;
  // The construction, in the local coordinates of `frame` (plane_frame.h):
  PlaneFrame frame;
  std::vector<Vec2> localPoints;             // P_i
  std::vector<std::array<Vec2, 4>> evolute;  // BP_k control points Q0..Q3, piece k: P_k -> P_k+1
};

// Checks points (finite, consecutive distinct, enough of them); throws as in the header.
void checkFairPoints(const std::vector<Vec2>& points, bool closed);
// brief: the checked points in their normalizing frame (PlaneFrame::normalizing), stored in *frame.
// throws: as checkFairPoints; also "points[j]" when P_j is distinct from its predecessor in world
//         coordinates but not in local ones (too close for the curve's size).
std::vector<Vec2> fairLocalPoints(const std::vector<Vec2>& points, bool closed, PlaneFrame* frame);
// |R_i| from the SMOOTHER / SHARPER relations (relations: N-1 entries open, N closed, or none).
// Magnitudes that are not finite and > 0 (points near the double range) are invalid_parameter at
// "points" (or "relations" when given).
std::vector<double> radiusMagnitudes(const std::vector<Vec2>& points, const std::vector<Relation>& relations,
                                     bool closed, double ratio = 1.5);
// The first estimation of the radius-vector angles, in degrees in [0, 180).
std::vector<double> firstEstimationAngles(const std::vector<Vec2>& points, bool closed);
// The curve for given angles (degrees, any real; read modulo 180) and magnitudes.
FairCurve buildFairCurve(const std::vector<Vec2>& points, const std::vector<double>& anglesDeg,
                         const std::vector<double>& magnitudes, bool closed, const EvoluteAlphas& alphas = {});

size_t pieceCount(const FairCurve& c);
// C_k(t) and dC_k/dt, t in [0, 1].
Vec2 fairCurvePoint(const FairCurve& c, size_t piece, double t);
Vec2 fairCurveDerivative(const FairCurve& c, size_t piece, double t);
// samplesPerPiece >= 2 points per piece, shared ends once: (samplesPerPiece - 1) * pieces + 1
// points (closed: the last equals the first). Throws invalid_parameter ("points") when a sample
// is not finite (a curve through points near the double range that bulges beyond it).
std::vector<Vec2> sampleFairCurve(const FairCurve& c, int samplesPerPiece);

// An angle read modulo 180, in [0, 180).
double normalizeAngle180(double deg);

}  // namespace fsdb
