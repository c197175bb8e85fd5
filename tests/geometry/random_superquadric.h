#pragma once
// Random superquadric parameters and points for the geometry tests (fixed seeds at call sites).
#include <cmath>
#include <random>

#include "geometry/superquadric/superquadric.h"
#include "geometry/core/vec3.h"

namespace fsdb {
namespace testing {

constexpr double kPi = 3.14159265358979323846;

// Undeformed parameters with the given shape exponents and sizes.
inline SuperquadricParams makeParams(double e1, double e2, double a1, double a2, double a3) {
  SuperquadricParams p;
  p.eps1 = e1;
  p.eps2 = e2;
  p.a1 = a1;
  p.a2 = a2;
  p.a3 = a3;
  return p;
}

// Valid parameters with every deformation active. When `injectiveBend` is set, kv is small
// enough for bendIsInjectiveOnPart; otherwise it may reach 0.95·π/C, the edge of the documented
// range.
inline SuperquadricParams randomParams(std::mt19937_64& rng, bool injectiveBend) {
  std::uniform_real_distribution<double> eps(0.1, 4.0), size(0.2, 5.0), ratio(0.2, 3.0),
      taper(-1.0, 1.0), twist(-6.0, 6.0), unit(-0.95, 0.95);
  SuperquadricParams p;
  p.eps1 = eps(rng);
  p.eps2 = eps(rng);
  p.a1 = size(rng);
  p.a2 = ratio(rng);
  p.a3 = ratio(rng);
  p.kx = taper(rng);
  p.ky = taper(rng);
  p.t = twist(rng);
  if (injectiveBend) {
    const double maxX = std::hypot(p.A() * (1 + std::fabs(p.kx)), p.B() * (1 + std::fabs(p.ky)));
    p.kv = unit(rng) / maxX;
  } else {
    p.kv = unit(rng) * kPi / p.C();
  }
  return p;
}

// Uniform in the canonical bounding box [−A, A] × [−B, B] × [−C, C] of the part.
inline Vec3 randomPointInBox(std::mt19937_64& rng, const SuperquadricParams& p) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {p.A() * u(rng), p.B() * u(rng), p.C() * u(rng)};
}

}  // namespace testing
}  // namespace fsdb
