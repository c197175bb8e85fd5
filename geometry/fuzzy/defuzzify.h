#pragma once
// Defuzzification: from a fuzzy set to crisp representatives.
//
// For a FuzzyNumber (normal, piecewise linear) the classic defuzzifiers are computed exactly
// from the breakpoints (no sampling):
//   centroid          ∫ x mu dx / ∫ mu dx
//   bisector          the x that splits the area under mu in halves (when a run of mu = 0
//                     makes the split point ambiguous: the middle of the ambiguous range)
//   smallest / mean / largest of maxima: over the set where mu = 1 (the core; for a
//                     non-convex number possibly several pieces). The mean weights pieces by
//                     length; when all pieces are points it is their plain mean.
// A crisp number gives its value. Any other membership of zero area (vertical spikes only)
// has no centroid or bisector; those return meanOfMaxima.
//
// localMaxima (Bernardes, Wu & D'Ottaviano, §5, defuzzification by local maxima) returns several
// ranked crisp candidates instead of one, so a designer can choose: every local maximum of a
// general piecewise-linear function (need not be normal or convex; may be a sampled function such
// as 180 samples over radius-vector angles), best first. Rules:
//  - the function is read on [x_front, x_back] only; an end counts when the function does not
//    rise from it (a boundary maximum);
//  - a plateau (consecutive breakpoints of equal mu, within 1e-12 of the largest |mu|) is one
//    maximum, reported at its midpoint;
//  - at a vertical jump the value is the larger side (as in piecewise_linear.h);
//  - Bernardes, Wu & D'Ottaviano, §7: maxima with mu < threshold (the alpha-cut R_alpha) are
//    dropped;
//  - order: mu descending, ties by x ascending.
// Errors: a malformed list throws errc::kInvalidParameter with path "[i]"; a non-finite
// threshold throws errc::kInvalidParameter with path "threshold".
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

struct RankedValue {
  double x;
  double mu;
};

double centroid(const FuzzyNumber& a);
double bisector(const FuzzyNumber& a);
double smallestOfMaxima(const FuzzyNumber& a);
double meanOfMaxima(const FuzzyNumber& a);
double largestOfMaxima(const FuzzyNumber& a);

std::vector<RankedValue> localMaxima(const std::vector<Breakpoint>& membership,
                                     double threshold = 0);

}  // namespace fsdb
