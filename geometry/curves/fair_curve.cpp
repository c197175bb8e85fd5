#include "geometry/curves/fair_curve.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {
namespace {

std::string pointPath(size_t i) { return "points[" + std::to_string(i) + "]"; }

Vec2 unit(const Vec2& v) { return (1.0 / length(v)) * v; }

// How far short of / beyond the crossing of two radius lines the inner control points stay.
constexpr double kConvexityMargin = 0.1;

using Polygon = std::array<Vec2, 4>;

// The piece's radius lines converge ahead of both points (A = D.tau_a, B = D.tau_b, c1 = n_b.tau_a,
// c2 = n_a.tau_b): the crossing X of the lines lies on the concave side, as for a circle.
// Lengths are local (about 1; plane_frame.h). Near 0 the crossing X lies at a point itself (the chord
// along a radius line, e.g. a closed curve through collinear points) and the convex polygon would
// collapse Q0 and Q1 onto it, leaving the PE no tangent there: such pieces take Table 1's depths.
constexpr double kConvexTolerance = 1e-9;
bool convex(double A, double B, double c1, double c2) {
  return A > kConvexTolerance && B > kConvexTolerance && c1 < -kConvexTolerance && c2 > kConvexTolerance;
}

// Convex piece: Q1 stays short of X (B - d1 c2 > 0) and Q2 beyond it (A + d2 c1 < 0), so the PE
// turns the way the curve advances at both ends and the strings keep one sign (a true involute
// of a point-like evolute is a circle: points on a circle give a near-circular piece).
Polygon convexPolygon(Vec2 pa, Vec2 na, Vec2 pb, Vec2 nb, double ra, double rb, double A, double B, double c1,
                      double c2, const EvoluteAlphas& a) {
  const double d1 = std::min(a.a3 * ra, (1 - kConvexityMargin) * B / c2);
  const double d2 = std::max(a.a2 * rb, (1 + kConvexityMargin) * A / -c1);
  const double d0 = d1 * (a.a4 / a.a3);  // Table 1's ratio alpha_4 / alpha_3
  const double d3 = d2 + (a.a1 - a.a2) * rb;
  return {pa + d0 * na, pa + d1 * na, pb + d2 * nb, pb + d3 * nb};
}

// Any other piece (an inflection between the points, or diverging radius lines): Table 1's depths,
// each end's pair in the order that makes the evolvent advance at both ends. With rho_0, rho_1 the
// signed strings (P = Q - rho T) and w = Q2 - Q1 that is rho_0 (tau_a.w) < 0 and rho_1 (tau_b.w) > 0
// (C'(0) = -rho_0 T'(0), C'(1) = -rho_1 T'(1)). The string may change sign inside: the curve then
// crosses its PE there, transversally (rho' != |BP'|), so no cusp. Orders with one sign are preferred.
Polygon tablePolygon(Vec2 pa, Vec2 na, Vec2 ta, Vec2 pb, Vec2 nb, Vec2 tb, double ra, double rb,
                     const EvoluteAlphas& a) {
  Polygon best{pa + a.a4 * ra * na, pa + a.a3 * ra * na, pb + a.a2 * rb * nb, pb + a.a1 * rb * nb};
  int bestRank = 0;
  for (int swapA = 0; swapA < 2; ++swapA)
    for (int swapB = 0; swapB < 2; ++swapB) {
      const double d0 = (swapA ? a.a3 : a.a4) * ra, d1 = (swapA ? a.a4 : a.a3) * ra;
      const double d2 = (swapB ? a.a1 : a.a2) * rb, d3 = (swapB ? a.a2 : a.a1) * rb;
      const Polygon q{pa + d0 * na, pa + d1 * na, pb + d2 * nb, pb + d3 * nb};
      const Vec2 w = q[2] - q[1];
      const double rho0 = d1 > d0 ? d0 : -d0, rho1 = d3 > d2 ? d3 : -d3;
      if (!(rho0 * dot(ta, w) < 0 && rho1 * dot(tb, w) > 0)) continue;
      const int rank = rho0 * rho1 > 0 ? 2 : 1;
      if (rank > bestRank) best = q, bestRank = rank;
    }
  return best;
}

// Cubic Bézier value, first and second derivative (Bernstein form).
Vec2 bezier(const std::array<Vec2, 4>& q, double t) {
  const double s = 1 - t;
  return (s * s * s) * q[0] + (3 * s * s * t) * q[1] + (3 * s * t * t) * q[2] + (t * t * t) * q[3];
}
Vec2 bezierD1(const std::array<Vec2, 4>& q, double t) {
  const double s = 1 - t;
  return (3 * s * s) * (q[1] - q[0]) + (6 * s * t) * (q[2] - q[1]) + (3 * t * t) * (q[3] - q[2]);
}
Vec2 bezierD2(const std::array<Vec2, 4>& q, double t) {
  return (6 * (1 - t)) * (q[2] - 2.0 * q[1] + q[0]) + (6 * t) * (q[3] - 2.0 * q[2] + q[1]);
}

// The string length rho(t) of the header and its derivative.
struct StringLength {
  double rho, drho;
};
StringLength stringLength(const FairCurve& c, size_t k, double t) {
  const auto& q = c.evolute[k];
  const size_t b = (k + 1) % c.localPoints.size();
  // Signed strings: P = Q - rho T at both ends.
  const double s0 = dot(q[0] - c.localPoints[k], unit(q[1] - q[0])),
               s1 = dot(q[3] - c.localPoints[b], unit(q[3] - q[2]));
  const double d0 = 3 * length(q[1] - q[0]), d1 = 3 * length(q[3] - q[2]);  // |BP'(0)|, |BP'(1)|
  const double lin = s1 - s0;
  const double h10 = t * t * t - 2 * t * t + t, h11 = t * t * t - t * t;
  const double dh10 = 3 * t * t - 4 * t + 1, dh11 = 3 * t * t - 2 * t;
  // Bernardes, Wu & D'Ottaviano, §2: linear interpolation of the magnitudes, plus the Hermite term
  // (header).
  return {(1 - t) * s0 + t * s1 + h10 * (d0 - lin) + h11 * (d1 - lin), lin + dh10 * (d0 - lin) + dh11 * (d1 - lin)};
}

// The unit PE tangent; where BP' vanishes (a PE cusp) the direction of BP'' (its limit).
Vec2 unitTangent(const std::array<Vec2, 4>& q, double t, double* speed) {
  const Vec2 d = bezierD1(q, t);
  *speed = length(d);
  if (*speed > 0) return (1.0 / *speed) * d;
  const Vec2 dd = bezierD2(q, t);
  return length(dd) > 0 ? unit(dd) : Vec2{1, 0};
}

}  // namespace

double normalizeAngle180(double deg) {
  double a = std::fmod(deg, 180.0);
  if (a < 0) a += 180.0;
  return a >= 180.0 ? 0.0 : a;
}

void checkFairPoints(const std::vector<Vec2>& points, bool closed) {
  const size_t n = points.size();
  if (n < (closed ? 3u : 2u))
    throw Error(errc::kInvalidParameter,
                std::string("a fair ") + (closed ? "closed curve needs at least 3" : "curve needs at least 2") +
                    " points, got " + std::to_string(n),
                "points");
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw Error(errc::kInvalidParameter, "point coordinates must be finite", pointPath(i));
  for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
    const size_t j = (i + 1) % n;
    if (points[i].x == points[j].x && points[i].y == points[j].y)
      throw Error(errc::kInvalidParameter,
                  "consecutive points must differ (" + pointPath(i) + " = " + pointPath(j) + ")", pointPath(j));
  }
}

std::vector<Vec2> fairLocalPoints(const std::vector<Vec2>& points, bool closed, PlaneFrame* frame) {
  checkFairPoints(points, closed);
  *frame = PlaneFrame::normalizing(points);
  std::vector<Vec2> local;
  local.reserve(points.size());
  for (const Vec2& p : points) local.push_back(frame->toLocal(p));
  const size_t n = points.size();
  for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
    const size_t j = (i + 1) % n;
    if (local[i].x == local[j].x && local[i].y == local[j].y)
      throw Error(errc::kInvalidParameter,
                  pointPath(i) + " and " + pointPath(j) + " are too close together for the size of the curve (" +
                      formatNumber(length(points[j] - points[i])) + " apart, coordinates up to " +
                      formatNumber(frame->toWorldLength(1.0)) + "): their difference is lost in rounding",
                  pointPath(j));
  }
  return local;
}

std::vector<double> radiusMagnitudes(const std::vector<Vec2>& worldPoints, const std::vector<Relation>& relations,
                                     bool closed, double ratio) {
  PlaneFrame frame;
  const std::vector<Vec2> points = fairLocalPoints(worldPoints, closed, &frame);
  const size_t n = points.size();
  const size_t steps = closed ? n : n - 1;
  if (!relations.empty() && relations.size() != steps)
    throw Error(errc::kInvalidParameter,
                "relations needs " + std::to_string(steps) + " entries (one per point after the first" +
                    (closed ? ", and P_1 against P_N" : "") + "), got " + std::to_string(relations.size()),
                "relations");
  if (!(ratio > 1) || !std::isfinite(ratio))
    throw Error(errc::kInvalidParameter, "the relation ratio must be finite and > 1, got " + formatNumber(ratio),
                "ratio");
  double chord = 0;
  for (size_t k = 0; k < steps; ++k) chord += length(points[(k + 1) % n] - points[k]);
  chord /= static_cast<double>(steps);

  // Bernardes, Wu & D'Ottaviano, §4: only the relative magnitudes matter; SMOOTHER = larger radius
  // than the predecessor.
  std::vector<double> step(steps, 0.0);
  double drift = 0;
  for (size_t k = 0; k < relations.size(); ++k) drift += step[k] = relations[k] == Relation::kSmoother ? 1.0 : -1.0;
  if (closed && !relations.empty()) {
    if (std::abs(drift) == static_cast<double>(n))
      throw Error(errc::kInvalidParameter,
                  "a closed curve's relations cannot all be '" + std::string(drift > 0 ? "smoother" : "sharper") +
                      "': the radii would have to grow all the way round",
                  "relations");
    for (double& s : step) s -= drift / static_cast<double>(n);
  }
  std::vector<double> e(n, 0.0);
  for (size_t i = 1; i < n; ++i) e[i] = e[i - 1] + step[i - 1];
  double mean = 0;
  for (double v : e) mean += v;
  mean /= static_cast<double>(n);
  std::vector<double> r(n);
  for (size_t i = 0; i < n; ++i) {
    r[i] = frame.toWorldLength(chord * std::pow(ratio, e[i] - mean));
    // Points near the double range (or a long run of one relation on a huge or tiny chord) leave
    // no representable radius: the request's fault, named by its field, not buildFairCurve's.
    if (!std::isfinite(r[i]) || !(r[i] > 0))
      throw Error(errc::kInvalidParameter,
                  "the radius-vector magnitudes are not representable (the points are too far apart or too close, "
                  "or too many relations in a row); got " +
                      formatNumber(r[i]) + " at " + pointPath(i),
                  relations.empty() ? "points" : "relations");
  }
  return r;
}

std::vector<double> firstEstimationAngles(const std::vector<Vec2>& worldPoints, bool closed) {
  PlaneFrame frame;  // angles do not depend on the frame
  const std::vector<Vec2> points = fairLocalPoints(worldPoints, closed, &frame);
  const size_t n = points.size();
  std::vector<double> angles(n);
  for (size_t i = 0; i < n; ++i) {
    const bool first = !closed && i == 0, last = !closed && i + 1 == n;
    if (first || last) {  // the normal of the end chord
      angles[i] = normalizeAngle180(degreesOf(first ? points[1] - points[0] : points[i] - points[i - 1]) + 90);
      continue;
    }
    const Vec2 toPrev = unit(points[(i + n - 1) % n] - points[i]), toNext = unit(points[(i + 1) % n] - points[i]);
    const Vec2 bisector = toPrev + toNext;
    angles[i] = normalizeAngle180(length(bisector) > 1e-12 ? degreesOf(bisector) : degreesOf(toNext) + 90);
  }
  return angles;
}

FairCurve buildFairCurve(const std::vector<Vec2>& worldPoints, const std::vector<double>& anglesDeg,
                         const std::vector<double>& magnitudes, bool closed, const EvoluteAlphas& a) {
  FairCurve c;
  const std::vector<Vec2> points = fairLocalPoints(worldPoints, closed, &c.frame);
  const size_t n = points.size();
  if (anglesDeg.size() != n || magnitudes.size() != n)
    throw Error(errc::kInvalidParameter, "one angle and one magnitude per point are needed", "angles");
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(anglesDeg[i]))
      throw Error(errc::kInvalidParameter, "angles must be finite", "angles[" + std::to_string(i) + "]");
    if (!(magnitudes[i] > 0) || !std::isfinite(magnitudes[i]))
      throw Error(errc::kInvalidParameter, "magnitudes must be finite and > 0",
                  "magnitudes[" + std::to_string(i) + "]");
  }
  if (!(a.a3 > a.a4 && a.a4 > 0 && a.a1 > a.a2 && a.a2 > 0))
    throw Error(errc::kInvalidParameter, "evolute alphas need a3 > a4 > 0 and a1 > a2 > 0", "alphas");

  std::vector<double> local(n);  // the magnitudes in local units
  for (size_t i = 0; i < n; ++i) {
    local[i] = c.frame.toLocalLength(magnitudes[i]);
    if (!(local[i] > 0) || !std::isfinite(local[i]))
      throw Error(errc::kInvalidParameter,
                  "magnitude " + formatNumber(magnitudes[i]) + " is out of proportion to the points (" +
                      formatNumber(c.frame.toWorldLength(1.0)) + " across)",
                  "magnitudes[" + std::to_string(i) + "]");
  }
  c.points = worldPoints;
  c.localPoints = points;
  c.closed = closed;
  // Orientation of each radius-vector (header): the concave side, else the predecessor's side.
  std::vector<Vec2> dir(n);
  for (size_t i = 0; i < n; ++i) dir[i] = unitAtDegrees(anglesDeg[i]);
  std::vector<bool> decided(n, false);
  for (size_t i = 0; i < n; ++i) {
    // An open end has one neighbour: the concave side is the side of its chord.
    const Vec2 prev = closed || i > 0 ? points[(i + n - 1) % n] : points[i];
    const Vec2 next = closed || i + 1 < n ? points[(i + 1) % n] : points[i];
    const Vec2 concave = prev + next - 2.0 * points[i];
    const double side = dot(dir[i], concave);
    if (std::abs(side) > 1e-12 * length(concave) && length(concave) > 0) {
      if (side < 0) dir[i] = -dir[i];
      decided[i] = true;
    }
  }
  for (size_t pass = 0; pass < 2; ++pass)  // undecided points follow a decided neighbour
    for (size_t i = 0; i < n; ++i) {
      if (decided[i]) continue;
      const size_t prev = (i + n - 1) % n, next = (i + 1) % n;
      const bool hasPrev = closed || i > 0, hasNext = closed || i + 1 < n;
      const int ref = hasPrev && decided[prev]   ? static_cast<int>(prev)
                      : hasNext && decided[next] ? static_cast<int>(next)
                                                 : -1;
      if (ref < 0 && pass == 0) continue;
      if (ref >= 0 && dot(dir[i], dir[ref]) < 0) dir[i] = -dir[i];
      decided[i] = true;
    }
  c.radii.resize(n);
  for (size_t i = 0; i < n; ++i) c.radii[i] = magnitudes[i] * dir[i];
  // Forward tangents: perpendicular to R_i, along the travel P_{i-1} -> P_{i+1}.
  std::vector<Vec2> tau(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 travel = (closed || i + 1 < n ? points[(i + 1) % n] : points[i]) -
                        (closed || i > 0 ? points[(i + n - 1) % n] : points[i]);
    tau[i] = Vec2{-dir[i].y, dir[i].x};
    if (dot(tau[i], travel) < 0) tau[i] = -tau[i];
  }
  // Bernardes, Wu & D'Ottaviano, §2: B_j = P_i + alpha_j R_i (j = 1, 2), B_j = P_{i-1} + alpha_j
  // R_{i-1} (j = 3, 4), "alpha_j chosen so that the convexity of the Bézier polygon is ensured"
  // (header).
  const size_t pieces = closed ? n : n - 1;
  for (size_t k = 0; k < pieces; ++k) {
    const size_t b = (k + 1) % n;
    const Vec2 D = points[b] - points[k];
    const double ra = local[k], rb = local[b];
    const double A = dot(D, tau[k]), B = dot(D, tau[b]);
    const double c1 = dot(dir[b], tau[k]), c2 = dot(dir[k], tau[b]);
    c.evolute.push_back(convex(A, B, c1, c2)
                            ? convexPolygon(points[k], dir[k], points[b], dir[b], ra, rb, A, B, c1, c2, a)
                            : tablePolygon(points[k], dir[k], tau[k], points[b], dir[b], tau[b], ra, rb, a));
  }
  return c;
}

size_t pieceCount(const FairCurve& c) { return c.evolute.size(); }

Vec2 fairCurvePoint(const FairCurve& c, size_t k, double t) {
  // The evolvent construction (Bernardes, Wu & D'Ottaviano, §2, Appendix A): the PE tangents are
  // the curve normals.
  double speed;
  const Vec2 T = unitTangent(c.evolute.at(k), t, &speed);
  return c.frame.toWorld(bezier(c.evolute[k], t) - stringLength(c, k, t).rho * T);
}

Vec2 fairCurveDerivative(const FairCurve& c, size_t k, double t) {
  const auto& q = c.evolute.at(k);
  double speed;
  const Vec2 T = unitTangent(q, t, &speed);
  const Vec2 d1 = bezierD1(q, t), d2 = bezierD2(q, t);
  // T' = (BP'' - (BP''.T) T) / |BP'|; at a PE cusp (speed 0) T is constant to first order.
  const Vec2 dT = speed > 0 ? (1.0 / speed) * (d2 - dot(d2, T) * T) : Vec2{0, 0};
  const StringLength s = stringLength(c, k, t);
  return c.frame.toWorldVector(d1 - s.drho * T - s.rho * dT);
}

std::vector<Vec2> sampleFairCurve(const FairCurve& c, int samplesPerPiece) {
  if (samplesPerPiece < 2)
    throw Error(errc::kInvalidParameter, "samples per piece must be at least 2, got " + std::to_string(samplesPerPiece),
                "samples");
  std::vector<Vec2> out;
  out.reserve(pieceCount(c) * static_cast<size_t>(samplesPerPiece - 1) + 1);
  for (size_t k = 0; k < pieceCount(c); ++k)
    for (int s = k == 0 ? 0 : 1; s < samplesPerPiece; ++s) {
      out.push_back(fairCurvePoint(c, k, static_cast<double>(s) / (samplesPerPiece - 1)));
      if (!std::isfinite(out.back().x) || !std::isfinite(out.back().y))
        throw Error(errc::kInvalidParameter,
                    "the curve through these points leaves the range of doubles (piece " + std::to_string(k) +
                        "); move the points nearer to the origin",
                    "points");
    }
  return out;
}

}  // namespace fsdb
