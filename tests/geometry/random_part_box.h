#pragma once
// Random part boxes (every one of the fourteen values an interval around a random valid part) and
// sampled F over them, for the enclosure tests (superquadric_slopes_test, superquadric_affine_test).
#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/superquadric/superquadric_bounds.h"
#include "geometry/superquadric/superquadric_slopes.h"
#include "tests/geometry/random_superquadric.h"

namespace fsdb {
namespace testing {

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// The crisp part whose fourteen values are v (slot order), axis from the box.
inline PlacedSuperquadric partAt(const PartBox& box, const double (&v)[kPartSlots]) {
  return partFromSlots(box.placement.axis, v);
}

// A random parameter vector of the box: a random corner for odd s, else a uniform point.
inline PlacedSuperquadric sampledPart(std::mt19937_64& rng, const PartBox& box, int s) {
  double v[kPartSlots];
  for (int i = 0; i < kPartSlots; ++i) {
    const Interval& w = partSlot(box, i);
    v[i] = (s & 1) ? ((rng() & 1) ? w.lo : w.hi) : uniform(rng, w.lo, w.hi);
  }
  return partAt(box, v);
}

// F at a sampled parameter vector of the box (sampledPart).
inline double sampledValue(std::mt19937_64& rng, const PartBox& box, int s, const Vec3& p) {
  return sampledPart(rng, box, s).insideOutside(p);
}

// A small box of every value around a random valid part (kv kept away from 0 and far from the
// limit, so that the bend's slopes are defined), relative half widths up to `relative`.
inline PartBox randomBox(std::mt19937_64& rng, double relative) {
  for (;;) {
    SuperquadricParams q = randomParams(rng, true);
    q.eps1 = std::min(std::max(q.eps1, 0.3), 3.5);
    q.eps2 = std::min(std::max(q.eps2, 0.3), 3.5);
    q.kx = std::max(-0.8, std::min(0.8, q.kx));
    q.ky = std::max(-0.8, std::min(0.8, q.ky));
    if (std::fabs(q.kv) < 0.02) q.kv = 0.02;
    PlacedSuperquadric c;
    c.params = q;
    c.placement = {{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)},
                   {uniform(rng, -1, 1), uniform(rng, -1, 1), 1.0},
                   uniform(rng, -90, 90),
                   uniform(rng, 0.5, 2)};
    PartBox box = crispPartBox(c);
    for (int i = 0; i < kPartSlots; ++i) {
      Interval& v = partSlot(box, i);
      const double s = relative * std::max(std::fabs(v.lo), 0.1) * uniform(rng, 0.2, 1.0);
      v = {v.lo - s, v.hi + s};
    }
    if (box.params.kv.lo * box.params.kv.hi <= 0.0) continue;
    return box;
  }
}

}  // namespace testing
}  // namespace fsdb
