#include "geometry/superquadric_affine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/deformation.h"
#include "geometry/interval_functions.h"
#include "geometry/transform.h"
#include "random_part_box.h"
#include "random_superquadric.h"

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
