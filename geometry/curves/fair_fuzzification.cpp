#include "geometry/curves/fair_fuzzification.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "geometry/curves/fair_curve.h"
#include "geometry/operators/tnorms.h"

namespace fsdb {
namespace {

double angleOf(const Vec2& v) { return normalizeAngle180(degreesOf(v)); }

int sign(double v) { return (v > 0) - (v < 0); }

void checkDelta(double deltaTheta) {
  if (!(deltaTheta > 0 && deltaTheta <= 90))
    throw Error(errc::kInvalidParameter, "delta_theta must lie in (0, 90], got " + formatNumber(deltaTheta),
                "delta_theta");
}

}  // namespace

double directionDistance(double a, double b) {
  const double d = normalizeAngle180(a - b);
  return std::min(d, 180.0 - d);
}

double dangerAngleMembership(double theta, double danger, double deltaTheta) {
  // Bernardes, Wu & D'Ottaviano, Figure 3: 0 at theta_c, 1 at theta_c + delta_theta, linear
  // between.
  return std::min(1.0, directionDistance(theta, danger) / deltaTheta);
}

double dangerArcMembership(double theta, const AngleArc& arc) {
  // Bernardes, Wu & D'Ottaviano, Figure 4: 0 on the danger zone, 1 at the furthest angle, linear
  // between.
  const double offset = normalizeAngle180(theta - arc.start);
  if (offset <= arc.length) return 0.0;
  const double half = 0.5 * (180.0 - arc.length);
  if (half <= 0) return 0.0;
  return std::min(1.0, std::min(offset - arc.length, 180.0 - offset) / half);
}

FairDangerZones fairDangerZones(const std::vector<Vec2>& worldPoints, const std::vector<double>& anglesDeg, bool closed,
                                size_t i, FairBehavior behavior) {
  PlaneFrame frame;  // directions and the signs of cross products do not depend on it
  const std::vector<Vec2> points = fairLocalPoints(worldPoints, closed, &frame);
  const size_t n = points.size();
  if (anglesDeg.size() != n) throw Error(errc::kInvalidParameter, "one angle per point is needed", "angles");
  FairDangerZones z;
  std::vector<size_t> neighbours;
  if (closed || i > 0) neighbours.push_back((i + n - 1) % n);
  if (closed || i + 1 < n) neighbours.push_back((i + 1) % n);
  for (size_t j : neighbours) {
    z.colinear.push_back(angleOf(points[i] - points[j]));   // Bernardes, Wu & D'Ottaviano, §4 G1
    z.parallel.push_back(normalizeAngle180(anglesDeg[j]));  // Bernardes, Wu & D'Ottaviano, §4 G2
  }
  if (behavior == FairBehavior::kUndulant || neighbours.size() < 2) return z;

  // Bernardes, Wu & D'Ottaviano, §4 G3: sign(t_{i-1} t_{i+1}) = sign(N_{i-1} N_{i+1}) sign(sin(phi_{i-1} - theta)
  // sin(phi_{i+1} - theta)).
  const size_t p = neighbours[0], q = neighbours[1];
  const Vec2 vp = unitAtDegrees(anglesDeg[p]), vq = unitAtDegrees(anglesDeg[q]);
  const int nSign = sign(cross(points[p] - points[i], vp)) * sign(cross(points[q] - points[i], vq));
  if (nSign == 0) return z;  // a neighbour on P_i's radius line: no G3 zone (header)
  z.hasIntersectionCondition = true;
  auto oppositeSides = [&](double theta) {
    const Vec2 u = unitAtDegrees(theta);
    return nSign * sign(cross(u, vp)) * sign(cross(u, vq)) < 0;
  };
  const double a = normalizeAngle180(anglesDeg[p]), b = normalizeAngle180(anglesDeg[q]);
  const double len = normalizeAngle180(b - a);
  const bool wantOpposite = behavior == FairBehavior::kNoInflection;  // G31 flags odd crossings
  if (len == 0) {  // equal neighbour directions: the sign is the same at every other angle
    const bool everywhere = oppositeSides(a + 90) == wantOpposite;
    z.intersection = AngleArc{a, everywhere ? 180.0 : 0.0};
  } else {
    const bool firstArc = oppositeSides(a + 0.5 * len) == wantOpposite;
    z.intersection = firstArc ? AngleArc{a, len} : AngleArc{b, 180.0 - len};
  }
  return z;
}

double fairMembership(const FairDangerZones& z, double theta, double deltaTheta) {
  // Bernardes, Wu & D'Ottaviano, §4 Figures 5, 6: the sets hold simultaneously, so AND (min, §3)
  // them.
  double mu = 1.0;
  for (double c : z.colinear) mu = zadehTNorm(mu, dangerAngleMembership(theta, c, deltaTheta));
  for (double c : z.parallel) mu = zadehTNorm(mu, dangerAngleMembership(theta, c, deltaTheta));
  if (z.hasIntersectionCondition) mu = zadehTNorm(mu, dangerArcMembership(theta, *z.intersection));
  return mu;
}

std::vector<Breakpoint> sampledFairSet(const FairDangerZones& z, int samples, double deltaTheta) {
  if (samples < 4)
    throw Error(errc::kInvalidParameter, "angle samples must be at least 4, got " + std::to_string(samples), "samples");
  checkDelta(deltaTheta);
  std::vector<Breakpoint> f(static_cast<size_t>(samples));
  for (int k = 0; k < samples; ++k) {
    const double x = 180.0 * k / samples;
    f[static_cast<size_t>(k)] = {x, fairMembership(z, x, deltaTheta)};
  }
  return f;
}

std::vector<RankedValue> fairAngleMaxima(const FairDangerZones& z, int samples, double threshold, double deltaTheta) {
  if (!std::isfinite(threshold) || threshold < 0 || threshold > 1)
    throw Error(errc::kInvalidParameter, "R_alpha must lie in [0, 1], got " + formatNumber(threshold),
                "alpha_threshold");
  const std::vector<Breakpoint> f = sampledFairSet(z, samples, deltaTheta);
  // Periodic reading: start at a smallest sample and close the period with it again.
  const size_t n = f.size();
  const size_t k0 = static_cast<size_t>(
      std::min_element(f.begin(), f.end(), [](const Breakpoint& a, const Breakpoint& b) { return a.mu < b.mu; }) -
      f.begin());
  const double h = 180.0 / static_cast<double>(n);
  std::vector<Breakpoint> periodic(n + 1);
  for (size_t j = 0; j <= n; ++j) periodic[j] = {f[k0].x + h * static_cast<double>(j), f[(k0 + j) % n].mu};

  std::vector<RankedValue> out;
  for (RankedValue m : localMaxima(periodic)) {  // Bernardes, Wu & D'Ottaviano, §5: defuzzification by local maxima
    // Refine on the exact (piecewise-linear, unimodal near the peak) set between the neighbours.
    double lo = m.x - h, hi = m.x + h;
    for (int it = 0; it < 60; ++it) {
      const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
      if (fairMembership(z, a, deltaTheta) < fairMembership(z, b, deltaTheta)) lo = a;
      else hi = b;
    }
    const double x = 0.5 * (lo + hi), mu = fairMembership(z, x, deltaTheta);
    if (mu > m.mu) m = {x, mu};
    m.x = normalizeAngle180(m.x);
    // Bernardes, Wu & D'Ottaviano, §7: the alpha-cut R_alpha discards improbable maxima; grade 0 is
    // never fair.
    if (m.mu > 0 && m.mu >= threshold) out.push_back(m);
  }
  std::sort(out.begin(), out.end(),
            [](const RankedValue& a, const RankedValue& b) { return a.mu != b.mu ? a.mu > b.mu : a.x < b.x; });
  return out;
}

}  // namespace fsdb
