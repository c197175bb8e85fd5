#include "geometry/core/number_format.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace fsdb {

std::string formatNumber(double x) {
  char buf[32];
  // 17 significant digits always round-trip; try fewer first for the shortest text.
  int precision = 1;
  for (; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  // %g with few digits writes 10 as "1e+01": more digits may give a shorter fixed form ("10").
  std::string best = buf;
  if (best.find('e') == std::string::npos) return best;
  for (++precision; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, x);
    if (std::strchr(buf, 'e') == nullptr) {
      if (std::strlen(buf) < best.size() && std::strtod(buf, nullptr) == x) best = buf;
      break;
    }
  }
  return best;
}

}  // namespace fsdb
