#include "geometry/fuzzy/fuzzy_similarity.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

double expectedMembership(const FuzzyNumber& a, const FuzzyNumber& b) {
  const double areaA = a.cardinality();
  if (areaA == 0) return heightOfIntersection(a, b);
  // Between consecutive breakpoints of either set both memberships are linear, so their product
  // is quadratic there and two-point Gauss-Legendre is exact; its nodes lie inside the piece, off
  // any vertical side.
  std::vector<double> xs;
  for (const Breakpoint& p : a.breakpoints()) xs.push_back(p.x);
  for (const Breakpoint& p : b.breakpoints()) xs.push_back(p.x);
  std::sort(xs.begin(), xs.end());
  const double lo = a.breakpoints().front().x, hi = a.breakpoints().back().x;
  const double g = 0.5 / std::sqrt(3.0);
  double sum = 0.0;
  for (size_t i = 0; i + 1 < xs.size(); ++i) {
    const double x0 = std::max(xs[i], lo), x1 = std::min(xs[i + 1], hi);
    if (!(x1 > x0)) continue;
    const double mid = 0.5 * (x0 + x1), w = x1 - x0;
    for (const double x : {mid - g * w, mid + g * w}) sum += 0.5 * w * a.membership(x) * b.membership(x);
  }
  return ratioOfAreas(sum / areaA);
}

}  // namespace fsdb
