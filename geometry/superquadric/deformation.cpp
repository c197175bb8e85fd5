#include "geometry/superquadric/deformation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/numeric/interval_functions.h"

namespace fsdb {

namespace {

// sin(u)/u, = 1 at u = 0. Below |u| = 1e-4 the next series term u⁴/120 is < 1e-18: the
// two-term series is exact to rounding and avoids 0/0.
double sinc(double u) {
  if (std::fabs(u) < 1e-4) return 1.0 - u * u / 6.0;
  return std::sin(u) / u;
}

// x / f where the taper factor f may vanish (only at |z| >= C, outside the part): no
// finite preimage exists there unless x = 0, see deformation.h.
double divideByTaperFactor(double x, double f) {
  if (f != 0.0) return x / f;
  if (x == 0.0) return 0.0;
  return std::copysign(std::numeric_limits<double>::infinity(), x);
}

}  // namespace

Vec3 taper(const SuperquadricParams& params, const Vec3& p) {
  if (params.kx == 0.0 && params.ky == 0.0) return p;  // the common untapered part: skip 3 ops
  // docs/api.md §2: X = x(kx·z/C + 1), Y = y(ky·z/C + 1).
  const double zc = p.z / params.C();
  return {p.x * (params.kx * zc + 1.0), p.y * (params.ky * zc + 1.0), p.z};
}

Vec3 untaper(const SuperquadricParams& params, const Vec3& p) {
  if (params.kx == 0.0 && params.ky == 0.0) return p;  // factors are exactly 1
  // Taper leaves z alone, so the deformed z gives the factors directly.
  const double zc = p.z / params.C();
  return {divideByTaperFactor(p.x, params.kx * zc + 1.0),
          divideByTaperFactor(p.y, params.ky * zc + 1.0), p.z};
}

Vec3 twist(const SuperquadricParams& params, const Vec3& p) {
  if (params.t == 0.0) return p;
  // docs/api.md §2: rotation about z by θ = t·z/C.
  const double theta = params.t * p.z / params.C();
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
}

Vec3 untwist(const SuperquadricParams& params, const Vec3& p) {
  if (params.t == 0.0) return p;
  // Twist leaves z alone: rotate back by the same θ.
  const double theta = params.t * p.z / params.C();
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * p.x + s * p.y, -s * p.x + c * p.y, p.z};
}

Vec3 bend(const SuperquadricParams& params, const Vec3& p) {
  const double k = params.kv;
  if (k == 0.0) return p;
  // Solina & Bajcsy 1990 bending with α = 0:
  //   X = 1/k − cos γ·(1/k − x),  Z = sin γ·(1/k − x),  γ = k·z.
  // Expanded so that no 1/k appears (it would cancel catastrophically as k -> 0):
  //   X = x cos γ + (1 − cos γ)/k = x cos γ + z·h·sinc²(h),   h = γ/2  (1 − cos γ = 2 sin² h)
  //   Z = sin γ/k − x sin γ       = z·sinc(γ) − x sin γ.
  const double gamma = k * p.z;
  const double h = 0.5 * gamma;
  const double sh = sinc(h);
  return {p.x * std::cos(gamma) + p.z * h * sh * sh, p.y,
          p.z * sinc(gamma) - p.x * std::sin(gamma)};
}

Vec3 unbend(const SuperquadricParams& params, const Vec3& p) {
  const double k = params.kv;
  if (k == 0.0) return p;
  // Inverse of Solina & Bajcsy's bend (α = 0). With s = 1 − k·x and γ = k·z the forward map
  // reads u = 1 − kX = s cos γ, v = kZ = s sin γ: polar coordinates about the bending axis.
  // The principal preimage (s > 0, γ in (−π, π]; deformation.h) is
  //   s = |(u, v)|,  γ = atan2(v, u),  x = (1 − s)/k,  z = γ/k.
  const double u = 1.0 - k * p.x;
  const double v = k * p.z;
  const double s = std::hypot(u, v);
  // x = (1 − s)/k cancels when s ~ 1 (small k or points near the z axis). Multiply by
  // (1 + s): 1 − s² = 1 − u² − v² = k·(X(1 + u) − v·Z), so x = (X(1 + u) − v·Z)/(1 + s),
  // which tends to X as k -> 0. Away from s ~ 1 there is no cancellation and the direct
  // form avoids overflow of X(1 + u) for |kX| >> 1.
  const double x =
      std::fabs(1.0 - s) < 0.5 ? (p.x * (1.0 + u) - v * p.z) / (1.0 + s) : (1.0 - s) / k;
  // z = atan2(v, u)/k. For u > 0 this is atan(v/u)/k = (Z/u)·atan(w)/w with w = v/u: no
  // division by a tiny k. u <= 0 needs |kX| >= 1, so k is not small there.
  const double z = u > 0.0 ? (p.z / u) * atanc(v / u) : std::atan2(v, u) / k;
  return {x, p.y, z};
}

Vec3 deformPoint(const SuperquadricParams& params, const Vec3& p) {
  return bend(params, twist(params, taper(params, p)));
}

Vec3 undeformPoint(const SuperquadricParams& params, const Vec3& p) {
  return untaper(params, untwist(params, unbend(params, p)));
}

bool bendIsInjectiveOnPart(const SuperquadricParams& params) {
  const double maxX = std::hypot(params.A() * (1.0 + std::fabs(params.kx)),
                                 params.B() * (1.0 + std::fabs(params.ky)));
  return std::fabs(params.kv) * maxX < 1.0;
}

double taperedHalfWidthFactor(double eps1, double k) {
  k = std::fabs(k);
  if (k == 0.0 || eps1 >= 2.0) return 1.0;
  const double q = 2.0 / eps1;
  // φ(w) = w^(q − 1)·(1 + 2kw) rises from 0 to 1 + 2k > k: one crossing, where the half-width's
  // logarithm (ε1/2)·log(1 − w^q) + log(1 + kw) turns.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double w = 0.5 * (lo + hi);
    (std::pow(w, q - 1.0) * (1.0 + 2.0 * k * w) < k ? lo : hi) = w;
  }
  const double w = 0.5 * (lo + hi);
  return std::max(1.0, std::pow(1.0 - std::pow(w, q), eps1 / 2.0) * (1.0 + k * w));
}

}  // namespace fsdb
