#include "geometry/core/parameter_check.h"

#include <cmath>
#include <cstdio>

#include "geometry/core/error.h"

namespace fsdb {

std::string formatRange(double min, bool minInclusive, double max, bool maxInclusive) {
  return std::string(minInclusive ? "[" : "(") + formatNumber(min) + ", " + formatNumber(max) +
         (maxInclusive ? "]" : ")");
}

bool inRange(double v, double min, bool minInclusive, double max, bool maxInclusive) {
  bool lowOk = minInclusive ? v >= min : v > min;
  bool highOk = maxInclusive ? v <= max : v < max;
  return lowOk && highOk;  // both false for NaN
}

void requireInRange(const std::string& name, double v, double min, bool minInclusive, double max,
                    bool maxInclusive) {
  if (inRange(v, min, minInclusive, max, maxInclusive)) return;
  throw Error(errc::kInvalidParameter,
              name + " must be in " + formatRange(min, minInclusive, max, maxInclusive) + "; got " +
                  formatNumber(v),
              name);
}

void requireDegree(const std::string& name, int n, int min, int max) {
  if (n >= min && n <= max) return;
  throw Error(errc::kInvalidParameter,
              name + " must be an integer in " + formatRange(min, true, max, true) + "; got " +
                  std::to_string(n),
              name);
}

}  // namespace fsdb
