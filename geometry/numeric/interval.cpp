#include "geometry/numeric/interval.h"

#include <algorithm>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

bool operator==(const Interval& a, const Interval& b) { return a.lo == b.lo && a.hi == b.hi; }
bool operator!=(const Interval& a, const Interval& b) { return !(a == b); }

Interval div(const Interval& a, const Interval& b) {
  if (contains(b, 0.0)) {
    throw Error(errc::kDomainError,
                "division by an interval that contains 0: [" + formatNumber(b.lo) + ", " +
                    formatNumber(b.hi) + "]",
                "divisor");
  }
  // 1/y is monotone decreasing on an interval that does not hold 0.
  return mul(a, Interval{1.0 / b.hi, 1.0 / b.lo});
}

Interval min(const Interval& a, const Interval& b) {
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}

Interval max(const Interval& a, const Interval& b) {
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

bool contains(const Interval& a, double x) { return a.lo <= x && x <= a.hi; }

bool contains(const Interval& outer, const Interval& inner) {
  return outer.lo <= inner.lo && inner.hi <= outer.hi;
}

double width(const Interval& a) { return a.hi - a.lo; }

Interval hull(const Interval& a, const Interval& b) {
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

}  // namespace fsdb
