#include "geometry/superquadric/superquadric_affine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/superquadric/deformation.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"
#include "tests/geometry/random_part_box.h"
#include "tests/geometry/random_superquadric.h"

namespace fsdb {
namespace {

using testing::randomBox;
using testing::sampledPart;
using testing::uniform;

// A point near the surface of the box's centre part.
Vec3 nearSurface(std::mt19937_64& rng, const PartBox& box) {
  const PlacedSuperquadric c = midpointPart(box);
  return placeToWorld(c.placement, deformPoint(c.params, testing::randomPointInBox(rng, c.params)));
}

// A point at G = g of the box's centre part (a canonical point scaled to G = g, G being
// homogeneous of degree 1, then deformed and placed): g = 1 is its surface.
Vec3 atLevel(std::mt19937_64& rng, const PartBox& box, double g) {
  const PlacedSuperquadric c = midpointPart(box);
  const Vec3 q = testing::randomPointInBox(rng, c.params);
  return placeToWorld(c.placement,
                      deformPoint(c.params, q * (g / homogeneousInsideOutside(c.params, q))));
}

// F at sampled (point, θ) of random boxes (every value an interval, corners and interior) lies in
// the enclosure, for point boxes and single points.
TEST(SuperquadricAffine, EnclosesSampledValues) {
  std::mt19937_64 rng(13);
  int nontrivial = 0, checked = 0;
  for (int k = 0; k < 400; ++k) {
    const PartBox box = randomBox(rng, k % 2 == 0 ? 0.02 : 0.002);
    const Vec3 p = nearSurface(rng, box);
    const double h = k % 4 < 2 ? 0.0 : 0.01 * uniform(rng, 0.1, 1.0);
    const Interval x{p.x - h, p.x + h}, y{p.y - h, p.y + h}, z{p.z - h, p.z + h};
    const Interval f = insideOutsideAffineBounds(box, x, y, z);
    ASSERT_LE(f.lo, f.hi);
    ASSERT_GE(f.lo, 0.0);
    if (f.hi < 1e300) ++nontrivial;
    for (int s = 0; s < 64; ++s) {
      const Vec3 q{uniform(rng, x.lo, x.hi + 1e-300), uniform(rng, y.lo, y.hi + 1e-300),
                   uniform(rng, z.lo, z.hi + 1e-300)};
      const double v = sampledPart(rng, box, s).insideOutside(s % 4 == 0 ? p : q);
      EXPECT_GE(v, f.lo - 1e-12 * (1 + v)) << k;
      EXPECT_LE(v, f.hi + 1e-12 * (1 + v)) << k;
      ++checked;
    }
  }
  EXPECT_GT(nontrivial, 300);
  EXPECT_GT(checked, 20000);
}

// One θ and one point: both ends are the crisp F.
TEST(SuperquadricAffine, DegenerateBoxIsTheCrispValue) {
  std::mt19937_64 rng(17);
  for (int k = 0; k < 200; ++k) {
    const PartBox box = crispPartBox(midpointPart(randomBox(rng, 0.0)));
    const Vec3 p = nearSurface(rng, box);
    const double f = midpointPart(box).insideOutside(p);
    const Interval a = insideOutsideAffineBounds(box, {p.x, p.x}, {p.y, p.y}, {p.z, p.z});
    if (a.hi >= 1e300) continue;  // a canonical ratio near 0: that term by intervals
    EXPECT_NEAR(a.lo, f, 1e-9 * (1 + f)) << k;
    EXPECT_NEAR(a.hi, f, 1e-9 * (1 + f)) << k;
  }
}

// The enclosure shrinks with the parameter box at least as fast as the box (its remainder is
// second order): ten times smaller boxes give at least nine times narrower enclosures; and over
// boxes of 0.2 % of every value it is narrower than the interval enclosure at most points.
TEST(SuperquadricAffine, ShrinksWithTheBoxAndBeatsIntervals) {
  std::mt19937_64 rng(19);
  int compared = 0, tighter = 0, quadratic = 0, scaled = 0;
  for (int k = 0; k < 200; ++k) {
    const PartBox box = randomBox(rng, 0.002);
    const Vec3 p = nearSurface(rng, box);
    const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
    const Interval a = insideOutsideAffineBounds(box, px, py, pz);
    if (a.hi >= 1e300) continue;
    const Interval i = insideOutsideBounds(box, px, py, pz);
    ++compared;
    tighter += width(a) < width(i);
    // The same box shrunk tenfold about its centre: the width of the linear part falls tenfold,
    // the remainder a hundredfold, so the total falls at least tenfold.
    PartBox small = box;
    for (int s = 0; s < kPartSlots; ++s) {
      Interval& v = partSlot(small, s);
      const double m = mid(v), r = 0.05 * width(v);
      v = {m - r, m + r};
    }
    const Interval b = insideOutsideAffineBounds(small, px, py, pz);
    ++scaled;
    quadratic += width(b) <= 0.11 * width(a) + 1e-12;
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(tighter, compared * 3 / 4);
  EXPECT_GT(quadratic, scaled * 9 / 10);
}

// Affine contraction keeps every sampled θ that qualifies (F <= 1 for inside, F > 1 otherwise),
// narrows some boxes, and reports an empty box only where no sampled θ qualifies.
TEST(SuperquadricAffine, ContractionKeepsEveryQualifyingTheta) {
  std::mt19937_64 rng(23);
  int narrowed = 0, emptied = 0, kept = 0;
  for (int k = 0; k < 600; ++k) {
    const PartBox box = randomBox(rng, k % 3 == 0 ? 0.05 : k % 3 == 1 ? 0.02 : 0.005);
    const Vec3 p = atLevel(rng, box, uniform(rng, 0.7, 1.3));
    const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
    AffineForm f;
    if (!insideOutsideAffineForm(box, px, py, pz, &f)) continue;
    for (const bool inside : {true, false}) {
      PartBox c = box;
      const bool nonEmpty = contractToQualifying(f, inside, &c);
      bool changed = false;
      for (int i = 0; i < kPartSlots; ++i) {
        const Interval& a = partSlot(box, i);
        const Interval& b = partSlot(c, i);
        EXPECT_GE(b.lo, a.lo);
        EXPECT_LE(b.hi, a.hi);
        changed = changed || a.lo != b.lo || a.hi != b.hi;
      }
      narrowed += nonEmpty && changed;
      emptied += !nonEmpty;
      for (int s = 0; s < 200; ++s) {
        double v[kPartSlots];
        for (int i = 0; i < kPartSlots; ++i) {
          const Interval& w = partSlot(box, i);
          // Corners, interior, and points at the contracted ends (the likeliest to be cut wrongly).
          const Interval& n = partSlot(c, i);
          const int pick = (s + i) % 4;
          v[i] = pick == 0 ? w.lo : pick == 1 ? w.hi : pick == 2 && nonEmpty ? uniform(rng, n.lo, n.hi) : uniform(rng, w.lo, w.hi);
        }
        const double value = testing::partAt(box, v).insideOutside(p);
        if (inside ? !(value <= 1.0) : !(value > 1.0)) continue;
        ++kept;
        ASSERT_TRUE(nonEmpty) << k;
        for (int i = 0; i < kPartSlots; ++i) {
          const Interval& n = partSlot(c, i);
          EXPECT_GE(v[i], n.lo) << k << " slot " << i;
          EXPECT_LE(v[i], n.hi) << k << " slot " << i;
        }
      }
    }
  }
  EXPECT_GT(narrowed, 20);
  EXPECT_GT(kept, 10000);
}

// Where the bend's 1 − kv·x may vanish (kv's interval holds 0), the trivial answer.
TEST(SuperquadricAffine, OutOfDomainIsTrivial) {
  PlacedSuperquadric c;
  c.params.kv = 0.0;
  PartBox box = crispPartBox(c);
  box.params.kv = {-0.1, 0.1};
  const Interval f = insideOutsideAffineBounds(box, {0.5, 0.5}, {0.0, 0.0}, {0.5, 0.5});
  EXPECT_EQ(f.lo, 0.0);
  EXPECT_GE(f.hi, 1e300);
}

}  // namespace
}  // namespace fsdb
