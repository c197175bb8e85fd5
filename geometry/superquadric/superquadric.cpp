#include "geometry/superquadric/superquadric.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxFinite = std::numeric_limits<double>::max();

// Shortest text that reads back as the same double, so a message shows the value the user sent.
[[noreturn]] void fail(const std::string& name, const std::string& range, double got) {
  throw Error(errc::kInvalidParameter, name + " must be " + range + "; got " + formatNumber(got),
              name);
}

// ||(a, b)||_p = (a^p + b^p)^(1/p) for a, b >= 0 and p > 0, without overflow or underflow:
// factoring out m = max(a, b) leaves (1 + r^p)^(1/p) with r = min/max in [0, 1], which is
// in [1, 2^(1/p)] however large p is (eps = 0.02 gives p = 100, and a^p alone would
// overflow for a > 1200). No negative number is ever raised to a fractional power.
double pNorm(double a, double b, double p) {
  const double m = std::max(a, b);
  if (m == 0.0 || std::isinf(m)) return m;
  const double r = std::min(a, b) / m;
  // The two exact special cases keep spheres and octahedra free of pow/exp rounding (and fast).
  if (p == 2.0) return m * std::sqrt(1.0 + r * r);
  if (p == 1.0) return m * (1.0 + r);
  return m * std::exp(std::log1p(std::pow(r, p)) / p);
}

}  // namespace

void SuperquadricParams::validate() const {
  // Written as !(in range) so that NaN, for which every comparison is false, is rejected too.
  if (!(eps1 > 0.0 && eps1 <= 4.0)) fail("eps1", "in (0, 4]", eps1);
  if (!(eps2 > 0.0 && eps2 <= 4.0)) fail("eps2", "in (0, 4]", eps2);
  if (!(a1 > 0.0 && std::isfinite(a1))) fail("a1", "a finite number > 0", a1);
  if (!(a2 > 0.0 && std::isfinite(a2))) fail("a2", "a finite number > 0", a2);
  if (!(a3 > 0.0 && std::isfinite(a3))) fail("a3", "a finite number > 0", a3);
  // The products can still leave the doubles (a1 = 1e200, a2 = 1e200); say which ratio did it.
  if (!(B() > 0.0 && std::isfinite(B())))
    fail("a2", "such that B = a1·a2 is a finite number > 0 (a1 = " + formatNumber(a1) + ")", a2);
  if (!(C() > 0.0 && std::isfinite(C())))
    fail("a3", "such that C = a1·a3 is a finite number > 0 (a1 = " + formatNumber(a1) + ")", a3);
  if (!(std::fabs(kx) <= 1.0)) fail("kx", "in [-1, 1]", kx);
  if (!(std::fabs(ky) <= 1.0)) fail("ky", "in [-1, 1]", ky);
  // |kv|·C < π keeps the bending angle kv·z of the part inside (−π, π): the bent part never
  // closes on itself and the bend can be undone (deformation.h).
  if (!(std::fabs(kv) * C() < kPi))
    fail("kv",
         "such that |kv|·C < π, i.e. |kv| < " + formatNumber(kPi / C()) +
             " for C = a1·a3 = " + formatNumber(C()),
         kv);
  if (!std::isfinite(t)) fail("t", "a finite number (radians)", t);
}

double homogeneousInsideOutside(const SuperquadricParams& params, const Vec3& p) {
  // docs/api.md §2 / Zhang, Pham & Chen, eq. 1: with X = |x|/A, Y = |y|/B, Z = |z|/C,
  //   F = (X^(2/eps2) + Y^(2/eps2))^(eps2/eps1) + Z^(2/eps1).
  // Let R = ||(X, Y)||_(2/eps2); then R^(2/eps1) = (X^(2/eps2) + Y^(2/eps2))^(eps2/eps1), so
  //   G = F^(eps1/2) = ||(R, Z)||_(2/eps1), a nest of two p-norms (each degree-1 homogeneous).
  const double X = std::fabs(p.x) / params.A();
  const double Y = std::fabs(p.y) / params.B();
  const double Z = std::fabs(p.z) / params.C();
  const double R = pNorm(X, Y, 2.0 / params.eps2);
  return pNorm(R, Z, 2.0 / params.eps1);
}

double insideOutside(const SuperquadricParams& params, const Vec3& p) {
  const double G = homogeneousInsideOutside(params, p);
  // F = G^(2/eps1). pow is monotone and pow(1, e) = 1 exactly, so F <= 1 iff G <= 1.
  const double F = params.eps1 == 1.0 ? G * G : std::pow(G, 2.0 / params.eps1);
  return std::min(F, kMaxFinite);
}

double pseudoDistance(const SuperquadricParams& params, const Vec3& p) {
  const double r = norm(p);
  if (r == 0.0) return -std::min({params.A(), params.B(), params.C()});
  if (std::isinf(r)) return kMaxFinite;
  // |p|·(1 − 1/G(p)) = |p| − 1/G(p/|p|) by homogeneity. Evaluating G on the unit direction
  // keeps it away from 0 and infinity for any |p|, and makes a sphere give exactly |p| − r.
  const double radius = 1.0 / homogeneousInsideOutside(params, p / r);
  return r - radius;
}

}  // namespace fsdb
