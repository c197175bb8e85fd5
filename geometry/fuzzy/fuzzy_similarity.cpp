#include "geometry/fuzzy/fuzzy_similarity.h"

#include <algorithm>

namespace fsdb {

double cardinalityOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b) {
  return area(pointwiseMin(a.breakpoints(), b.breakpoints()));
}

double heightOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b) {
  return height(pointwiseMin(a.breakpoints(), b.breakpoints()));
}

namespace {

// A ratio of areas in [0, 1], where one within kEqualAreas of 1 is 1: the areas of two sets equal
// but for rounding (a part made from words takes the words' set through its parameters, and its
// descriptor value comes back with other breakpoints) differ in the last bits, and S came out
// 0.9999999999999998, below a crisp value in the set's core, which scores exactly 1.
constexpr double kEqualAreas = 1e-12;
double ratioOfAreas(double r) { return r > 1 - kEqualAreas ? 1.0 : std::clamp(r, 0.0, 1.0); }

}  // namespace

double similarity(const FuzzyNumber& a, const FuzzyNumber& b) {
  if (a == b) return 1.0;  // the general formula gives 1 up to rounding
  const double areaA = a.cardinality(), areaB = b.cardinality();
  if (areaA == 0 || areaB == 0) {
    // Zhang, Pham & Chen, §5: for a crisp value x against a condition C, S = mu_C(x).
    return heightOfIntersection(a, b);
  }
  // Zhang, Pham & Chen, §5: S(A,B) = min(|A∩B|/|A|, |A∩B|/|B|)
  const double common = cardinalityOfIntersection(a, b);
  return ratioOfAreas(std::min(common / areaA, common / areaB));
}

double coverage(const FuzzyNumber& a, const FuzzyNumber& b) {
  if (a == b) return 1.0;
  const double areaA = a.cardinality(), areaB = b.cardinality();
  if (areaB == 0) return heightOfIntersection(a, b);
  if (areaA == 0) return 0.0;
  return ratioOfAreas(cardinalityOfIntersection(a, b) / areaB);
}

}  // namespace fsdb
