#include "geometry/curves/fair_candidates.h"

#include <algorithm>
#include <set>
#include <string>

#include "geometry/core/error.h"
#include "geometry/curves/fair_curve.h"
#include "geometry/operators/tnorms.h"

namespace fsdb {
namespace {

// Angles closer than this (degrees) are one angle.
constexpr double kSameAngleDeg = 1e-6;

double gradeAt(const std::vector<Vec2>& points, const std::vector<double>& angles, bool closed, size_t j,
               const FairCandidateOptions& o) {
  return fairMembership(fairDangerZones(points, angles, closed, j, o.behavior), angles[j], o.deltaTheta);
}

}  // namespace

std::vector<double> pointFairness(const std::vector<Vec2>& points, const std::vector<double>& anglesDeg, bool closed,
                                  FairBehavior behavior, double deltaTheta) {
  FairCandidateOptions o;
  o.behavior = behavior;
  o.deltaTheta = deltaTheta;
  std::vector<double> g(points.size());
  for (size_t j = 0; j < points.size(); ++j) g[j] = gradeAt(points, anglesDeg, closed, j, o);
  return g;
}

std::vector<FairCandidate> fairCandidates(const std::vector<Vec2>& points, bool closed, const FairCandidateOptions& o) {
  if (o.maxCandidates == 0)
    throw Error(errc::kInvalidParameter, "max_candidates must be at least 1", "max_candidates");
  const std::vector<double> base = firstEstimationAngles(points, closed);  // Bernardes, Wu & D'Ottaviano, Figure 7
  const size_t n = points.size();
  // Each point's set at the first estimation: its maxima give the candidates and its value at
  // the point's own angle is the grade every candidate keeps away from its changed angle.
  std::vector<FairDangerZones> baseZones;
  std::vector<double> baseGrades;
  for (size_t j = 0; j < n; ++j) {
    baseZones.push_back(fairDangerZones(points, base, closed, j, o.behavior));
    baseGrades.push_back(fairMembership(baseZones[j], base[j], o.deltaTheta));
  }
  std::vector<FairCandidate> out;
  for (size_t i = 0; i < n; ++i) {
    // Bernardes, Wu & D'Ottaviano, §5 (local maxima), §7 (R_alpha).
    for (const RankedValue& m : fairAngleMaxima(baseZones[i], o.angleSamples, o.alphaThreshold, o.deltaTheta)) {
      FairCandidate c{0, i, m.mu, base};
      // A maximum at the first estimation itself (within rounding) is the first-estimation curve.
      c.anglesDeg[i] = directionDistance(m.x, base[i]) < kSameAngleDeg ? base[i] : m.x;
      // The AND over all points; only P_i and its neighbours see the new angle.
      double score = 1.0;
      for (size_t j = 0; j < n; ++j) {
        const bool near = j == i || j + 1 == i || i + 1 == j || (closed && ((j + 1) % n == i || (i + 1) % n == j));
        score = zadehTNorm(score, near ? gradeAt(points, c.anglesDeg, closed, j, o) : baseGrades[j]);
      }
      c.score = score;
      out.push_back(std::move(c));
    }
  }
  std::sort(out.begin(), out.end(), [](const FairCandidate& a, const FairCandidate& b) {
    if (a.score != b.score) return a.score > b.score;
    if (a.membership != b.membership) return a.membership > b.membership;
    if (a.point != b.point) return a.point < b.point;
    return a.anglesDeg[a.point] < b.anglesDeg[b.point];
  });
  // One candidate per distinct curve: the best-ranked copy stays.
  std::set<std::vector<double>> seen;
  std::vector<FairCandidate> distinct;
  for (FairCandidate& c : out) {
    if (distinct.size() == o.maxCandidates) break;
    if (seen.insert(c.anglesDeg).second) distinct.push_back(std::move(c));
  }
  return distinct;
}

}  // namespace fsdb
