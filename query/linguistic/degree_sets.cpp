// See query/linguistic/degree_sets.h.
#include "query/linguistic/degree_sets.h"

#include <vector>

#include "geometry/fuzzy/fuzzy_arithmetic.h"

namespace fsdb {

FuzzyNumber restrictedToDegrees(const FuzzyNumber& set, double lo, double hi) {
  const std::vector<Breakpoint>& p = set.breakpoints();
  std::vector<Breakpoint> out;
  for (size_t i = 0; i < p.size(); ++i) {
    if (i > 0)
      for (double cut : {lo, hi})
        if ((p[i - 1].x < cut && p[i].x > cut) || (p[i - 1].x > cut && p[i].x < cut)) {
          const double t = (cut - p[i - 1].x) / (p[i].x - p[i - 1].x);
          out.push_back({cut, p[i - 1].mu + t * (p[i].mu - p[i - 1].mu)});
        }
    if (p[i].x >= lo && p[i].x <= hi) out.push_back(p[i]);
  }
  return FuzzyNumber::fromPoints(out);
}

FuzzyNumber withinDegrees(const FuzzyNumber& set, double lo, double hi) {
  // Only an end of the domain inside the scale cuts (a closest-match set widened below 0 keeps
  // its area there), and only where the set's core reaches inside the domain: cut there, the set
  // keeps a core. (The plain ramp of "square", 1 only at squariness 1, stays the ramp: an object
  // at 0.99 meets it at 0.99, as before.)
  const Interval core = set.core(), support = set.support();
  const bool cutLo = lo > 0.0 && support.lo < lo && core.hi >= lo;
  const bool cutHi = hi < 1.0 && support.hi > hi && core.lo <= hi;
  if (!cutLo && !cutHi) return set;
  return restrictedToDegrees(set, cutLo ? lo : support.lo, cutHi ? hi : support.hi);
}

// Exact: negation and a crisp shift.
FuzzyNumber mirroredDegrees(const FuzzyNumber& set) { return add(negate(set), FuzzyNumber::crisp(1.0)); }

}  // namespace fsdb
