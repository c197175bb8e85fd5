#pragma once
// Fuzzification and defuzzification of the radius-vector angles of a fair curve (Bernardes, Wu &
// D'Ottaviano, §4, §5, §7). For point P_i, with the other points' angles held, every angle theta in
// [0°, 180°) gets a grade of membership to the fair concept from the "danger zones" (§4):
//  - G1 (non-colinear): R_i must not lie along P_i - P_j, j = i-1, i+1. Figure 3: grade 0 at the
//    danger angle theta_c, 1 at theta_c + delta_theta (90° by default), linear between; read on
//    the circle of directions (period 180°), so the grade is min(1, d(theta, theta_c) / delta).
//  - G2 (non-parallel): R_i must not be parallel to R_j, j = i-1, i+1; the same shape (Figure 3).
//  - G3 (non-intersection, Figure 4): 0 on the danger zone, 1 at the angle furthest from it,
//    linear between. The zone, from the intersections I_{i-1} of the lines of R_{i-1} and R_i and
//    I_i of R_i and R_{i+1}: G31 (no inflection wanted) flags the angles whose I_{i-1}, I_i lie
//    on opposite sides of P_i along R_i (the segment I_{i-1} I_i crosses the curve at P_i: an odd
//    crossing), G32 (an inflection wanted) the angles with both on one side (even). Along the
//    line P_i + t u(theta), t_j = cross(P_j - P_i, R_j) / cross(u, R_j), so the sign of
//    t_{i-1} t_i changes only at the angles of R_{i-1} and R_{i+1}: each zone is one of the two
//    arcs between those angles (our reading of "crosses the convex hull of S"; the text is vague).
//    A point without both neighbours (the ends of an open curve), or lying on a neighbour's
//    radius line (then t = 0 for every angle), has no G3 zone (grade 1).
// The behaviours (§4): kUndulant is the set F_4 = G1(i-1) AND G1(i+1) AND G2(i-1) AND G2(i+1)
// (Figures 5, 6); kNoInflection is F_4 AND G31; kInflection is F_4 AND G32 (F_2, Figure 4).
// AND is min (§3, zadehTNorm). Defuzzification (§5) by local maxima (geometry/fuzzy/defuzzify.h
// localMaxima): the set is sampled at `samples` angles k 180° / samples, the samples are read
// as a periodic function (rotated to start at a smallest sample, so each maximum is seen once),
// and each local maximum is refined by a ternary search on the exact set between its two
// neighbouring samples (the sets are piecewise linear with kinks between samples). Maxima with
// a grade below the threshold R_alpha (§7) are dropped; best first, ties by angle.
// Errors: invalid_parameter for samples < 4 ("samples"), a non-finite or out-of-[0, 1] threshold
// ("alpha_threshold"), delta_theta outside (0, 90] ("delta_theta"), bad points (fair_curve.h).
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/fuzzy/defuzzify.h"
#include "geometry/core/vec2.h"

namespace fsdb {

enum class FairBehavior { kUndulant, kNoInflection, kInflection };

// An arc of directions [start, start + length] read modulo 180; length in [0, 180].
struct AngleArc {
  double start;
  double length;
};

// The danger zones of one point (§4), as danger angles and an optional G3 arc.
struct FairDangerZones {
  std::vector<double> colinear;   // G1: angles of P_i - P_j
  std::vector<double> parallel;   // G2: angles of R_j
  std::optional<AngleArc> intersection;  // G3 (G31 or G32 by the behaviour)
  bool hasIntersectionCondition = false;  // false: no G3 set (grade 1)
};

// The distance of two directions in degrees, in [0, 90].
double directionDistance(double a, double b);
// Figure 3 (G1, G2): min(1, d(theta, danger) / deltaTheta).
double dangerAngleMembership(double theta, double danger, double deltaTheta = 90);
// Figure 4 (G3): 0 on the arc, 1 at the direction furthest from it, linear between.
double dangerArcMembership(double theta, const AngleArc& arc);

FairDangerZones fairDangerZones(const std::vector<Vec2>& points, const std::vector<double>& anglesDeg, bool closed,
                                size_t i, FairBehavior behavior);
// The AND (min) of the point's sets at theta.
double fairMembership(const FairDangerZones& zones, double theta, double deltaTheta = 90);
// The set sampled at k 180 / samples, k = 0..samples-1, as breakpoints (x in degrees).
std::vector<Breakpoint> sampledFairSet(const FairDangerZones& zones, int samples, double deltaTheta = 90);
// §5, §7: the local maxima (x = angle in [0, 180), mu = grade), best first, grades >= threshold.
std::vector<RankedValue> fairAngleMaxima(const FairDangerZones& zones, int samples = 180, double threshold = 0,
                                         double deltaTheta = 90);

}  // namespace fsdb
