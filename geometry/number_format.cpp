#include "geometry/number_format.h"

#include <cstdio>
#include <cstdlib>

namespace fsdb {

std::string formatNumber(double x) {
  char buf[32];
  // 17 significant digits always round-trip; try fewer first for the shortest text.
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

}  // namespace fsdb
