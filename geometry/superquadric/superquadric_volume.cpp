#include "geometry/superquadric/superquadric_volume.h"

#include <cmath>

namespace fsdb {

double betaFunction(double a, double b) {
  // std::lgamma writes the global `signgam` in glibc (a benign race between threads: all
  // arguments here are positive, where Γ > 0 and nobody reads it).
  return std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

double canonicalVolume(const SuperquadricParams& params) {
  const double e1 = params.eps1, e2 = params.eps2;
  // Jaklič, Leonardis & Solina 2000, ch. 2: V = 2 a1 a2 a3 ε1 ε2 β(ε1/2 + 1, ε1) β(ε2/2, ε2/2),
  // their a1, a2, a3 being our half-lengths A, B, C.
  return 2.0 * params.A() * params.B() * params.C() * e1 * e2 * betaFunction(0.5 * e1 + 1.0, e1) *
         betaFunction(0.5 * e2, 0.5 * e2);
}

double taperVolumeFactor(const SuperquadricParams& params) {
  const double e1 = params.eps1;
  // 1 + kx·ky·<z²>/C², with <z²>/C² = β(3ε1/2, ε1 + 1) / (2 β(ε1/2 + 1, ε1)) (header).
  const double meanZ2 = betaFunction(1.5 * e1, e1 + 1.0) / (2.0 * betaFunction(0.5 * e1 + 1.0, e1));
  return 1.0 + params.kx * params.ky * meanZ2;
}

double superquadricVolume(const SuperquadricParams& params) {
  return canonicalVolume(params) * taperVolumeFactor(params);
}

double placedVolume(const PlacedSuperquadric& part) {
  const double s = part.placement.scale;
  return s * s * s * superquadricVolume(part.params);
}

}  // namespace fsdb
