#include "geometry/operators/tnorms.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/core/parameter_check.h"

namespace fsdb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// (a^p + b^p)^(1/p) for a, b >= 0, scaled by the larger term so that large p neither
// overflows nor underflows (0.3^1000 is 0 in double; the scaled form keeps the answer 0.7).
double scaledPNorm(double a, double b, double p) {
  double hi = std::max(a, b), lo = std::min(a, b);
  if (hi == 0.0) return 0.0;
  if (std::isinf(hi)) return kInf;
  return hi * std::pow(1.0 + std::pow(lo / hi, p), 1.0 / p);
}

}  // namespace

// Li & Tian, Table 1, algebraic
double algebraicTNorm(double x, double y) { return x * y; }

// Li & Tian, Table 1, Zadeh
double zadehTNorm(double x, double y) { return std::min(x, y); }

// Li & Tian, Table 1, Lukasiewicz
double lukasiewiczTNorm(double x, double y) { return std::max(0.0, x + y - 1.0); }

// Li & Tian, Table 1, Dubois-Prade
double duboisPradeTNorm(double x, double y, double k) {
  requireInRange("k", k, 0.0, false, 1.0, true);
  return x * y / std::max({x, y, k});
}

// Li & Tian, Table 1, Einstein
double einsteinTNorm(double x, double y) { return x * y / (2.0 - (x + y - x * y)); }

// Li & Tian, Table 1, Dombi. (1 - x)/x is 1/x - 1 without the cancellation near x = 1.
double dombiTNorm(double x, double y, double n) {
  requireInRange("n", n, 0.0, false, kInf, false);
  if (x == 0.0 || y == 0.0) return 0.0;
  return 1.0 / (1.0 + scaledPNorm((1.0 - x) / x, (1.0 - y) / y, n));
}

// Li & Tian, Table 1, Hamacher. The denominator vanishes only at x = y = 0 with a = 0, where the
// limit along every path inside [0,1]^2 is 0.
double hamacherTNorm(double x, double y, double a) {
  requireInRange("a", a, 0.0, true, 1.0, false);
  double denominator = a + (1.0 - a) * (x + y - x * y);
  return denominator == 0.0 ? 0.0 : x * y / denominator;
}

// Li & Tian, Table 1, Weber
double weberTNorm(double x, double y, double k) {
  requireInRange("k", k, -1.0, false, kInf, false);
  return std::max(0.0, (x + y + k * x * y - 1.0) / (1.0 + k));
}

// Li & Tian, Table 1, Yager (k in (1, inf) as printed; k = 1 would be Lukasiewicz)
double yagerTNorm(double x, double y, double k) {
  requireInRange("k", k, 1.0, false, kInf, false);
  return 1.0 - std::min(1.0, scaledPNorm(1.0 - x, 1.0 - y, k));
}

}  // namespace fsdb
