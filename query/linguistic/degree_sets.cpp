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

// Exact: negation and a crisp shift.
FuzzyNumber mirroredDegrees(const FuzzyNumber& set) { return add(negate(set), FuzzyNumber::crisp(1.0)); }

}  // namespace fsdb
