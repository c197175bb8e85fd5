#pragma once
// Ranked candidate fair curves (Bernardes, Wu & D'Ottaviano, §5, §6, §7): from the first estimation
// of the angles (fair_curve.h firstEstimationAngles; Figure 7), each point's fuzzy set
// (fair_fuzzification.h) is defuzzified by its local maxima, as the paper does for P1 of Figure 7
// (Figures 8-11: one curve per maximum, the other angles held). Each maximum gives one candidate:
// the first estimation with that point's angle replaced by the maximum. A candidate's score is the
// fairness of the whole curve: the AND (min, §3) over every point of its grade at the candidate's
// angles (the neighbours' grades change with the replaced angle through G2 and G3). Order: score
// descending, then the maximum's own grade, then point index, then angle; at most maxCandidates.
// A maximum within 1e-6° of the first estimation is the first-estimation curve itself, so
// several points can give that one curve: each distinct curve is listed once (its best copy).
// Maxima below R_alpha (alphaThreshold, §7) never become candidates.
// Errors: as fair_fuzzification.h and fair_curve.h; maxCandidates 0 is invalid_parameter
// ("max_candidates").
#include <cstddef>
#include <vector>

#include "geometry/curves/fair_fuzzification.h"
#include "geometry/core/vec2.h"

namespace fsdb {

struct FairCandidateOptions {
  FairBehavior behavior = FairBehavior::kNoInflection;
  double alphaThreshold = 0;  // R_alpha
  int angleSamples = 180;     // 1°, the resolution of the paper's maxima
  size_t maxCandidates = 10;
  double deltaTheta = 90;     // Figure 3's delta theta
};

struct FairCandidate {
  double score;                    // min over the points of their grades
  size_t point;                    // the point whose angle is a local maximum
  double membership;               // that maximum's grade
  std::vector<double> anglesDeg;   // every point's angle, [0, 180)
};

// The grade of each point at the given angles (its set's value at its own angle).
std::vector<double> pointFairness(const std::vector<Vec2>& points, const std::vector<double>& anglesDeg, bool closed,
                                  FairBehavior behavior, double deltaTheta = 90);

std::vector<FairCandidate> fairCandidates(const std::vector<Vec2>& points, bool closed,
                                          const FairCandidateOptions& options = {});

}  // namespace fsdb
