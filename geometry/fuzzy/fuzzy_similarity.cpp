#include "geometry/fuzzy/fuzzy_similarity.h"

#include <algorithm>

namespace fsdb {

double cardinalityOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b) {
  return area(pointwiseMin(a.breakpoints(), b.breakpoints()));
}

double heightOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b) {
  return height(pointwiseMin(a.breakpoints(), b.breakpoints()));
}

double similarity(const FuzzyNumber& a, const FuzzyNumber& b) {
  if (a == b) return 1.0;  // the general formula gives 1 up to rounding
  const double areaA = a.cardinality(), areaB = b.cardinality();
  if (areaA == 0 || areaB == 0) {
    // Zhang, Pham & Chen, §5: for a crisp value x against a condition C, S = mu_C(x).
    return heightOfIntersection(a, b);
  }
  // Zhang, Pham & Chen, §5: S(A,B) = min(|A∩B|/|A|, |A∩B|/|B|)
  const double common = cardinalityOfIntersection(a, b);
  return std::clamp(std::min(common / areaA, common / areaB), 0.0, 1.0);
}

}  // namespace fsdb
