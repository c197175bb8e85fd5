#pragma once
// Parameter checks shared by the operator math and the operator catalogue, so that a bad
// parameter produces the same fsdb::Error (errc::kInvalidParameter, path = parameter name,
// message = allowed range and the value given) whichever door it came through.
#include <string>

#include "geometry/core/number_format.h"  // formatNumber, for the messages of every check

namespace fsdb {

// "(0, 1]", "[1, 64]", "(-1, inf)".
std::string formatRange(double min, bool minInclusive, double max, bool maxInclusive);

// True when v lies in the range (NaN never does).
bool inRange(double v, double min, bool minInclusive, double max, bool maxInclusive);

// Throws Error(kInvalidParameter, "<name> must be in <range>; got <v>", name) unless inRange.
void requireInRange(const std::string& name, double v, double min, bool minInclusive, double max,
                    bool maxInclusive);

// Integer parameters (degrees): throws unless min <= n <= max.
void requireDegree(const std::string& name, int n, int min, int max);

}  // namespace fsdb
