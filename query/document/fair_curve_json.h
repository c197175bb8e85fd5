#pragma once
// The JSON form of a fair-curve request (POST /curves/fair; Bernardes, Wu & D'Ottaviano;
// docs/api.md §6):
//   {"points":[[x,y],...], "relations":["smoother"|"sharper",...], "closed":false,
//    "behavior":"no_inflection"|"undulant"|"inflection", "alpha_threshold":0,
//    "samples":32, "angle_samples":180, "max_candidates":10}
// points: at least 2 (closed: 3). relations (optional): relations[k] compares point k+1 (mod N)
// with point k, so N-1 entries open, N closed (geometry/curves/fair_curve.h radiusMagnitudes).
// behavior: which danger zones rank the angles (geometry/curves/fair_fuzzification.h): "undulant" =
// F_4 (G1, G2), "no_inflection" (default) = F_4 and G31, "inflection" = F_4 and G32.
// alpha_threshold: R_alpha in [0, 1] (§7). samples: curve points per piece (>= 2).
// angle_samples: samples of each fuzzy set over [0°, 180°) (>= 4; maxima are refined between).
// max_candidates: >= 1.
// Errors carry the JSON path: invalid_document for types and unknown keys ("points[2][1]",
// "relations[0]", "flag"), invalid_parameter for values out of range (422), limit_exceeded (413)
// naming the limit beyond FairCurveLimits ("points", "samples", "angle_samples", "max_candidates"):
// each limit is the `fsdb serve` option of the same name (--max-fair-points, ...).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "geometry/curves/fair_candidates.h"
#include "geometry/curves/fair_curve.h"

namespace fsdb {

struct FairCurveLimits {
  size_t maxPoints = 1000;          // max_fair_points: given points
  int maxSamples = 1000;            // max_fair_samples: curve points per piece
  int maxAngleSamples = 3600;       // max_fair_angle_samples
  size_t maxCandidates = 100;       // max_fair_candidates
  size_t maxCurvePoints = 1000000;  // max_fair_curve_points: candidates x pieces x samples in one answer
};

struct FairCurveRequest {
  std::vector<Vec2> points;
  std::vector<Relation> relations;
  bool closed = false;
  int samples = 32;
  FairCandidateOptions options;
};

FairCurveRequest parseFairCurveRequest(const nlohmann::json& body, const FairCurveLimits& limits = {});
const char* behaviorName(FairBehavior b);

// What a request yields (POST /curves/fair, and a stored fair curve's GET /curves/{id}/candidates
// and /svg): the radius magnitudes |R_i| and the candidates best first (geometry/curves/fair_candidates.h),
// curves[k] being candidates[k]'s curve sampled with `samples` points per piece.
struct FairCurveAnswer {
  std::vector<double> radii;
  std::vector<FairCandidate> candidates;
  std::vector<std::vector<Vec2>> curves;
};
FairCurveAnswer answerFairCurve(const FairCurveRequest& request);
// {"candidates":[{"score","point","membership","angles_deg","curve":[[x,y],...]}],
//  "first_estimation_deg","radii","behavior"}
nlohmann::json fairCurveAnswerJson(const FairCurveRequest& request, const FairCurveAnswer& answer);

}  // namespace fsdb
