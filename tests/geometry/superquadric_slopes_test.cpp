#include "geometry/superquadric_slopes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/deformation.h"
#include "geometry/interval_functions.h"
#include "geometry/transform.h"
#include "random_part_box.h"
#include "random_superquadric.h"

namespace fsdb {
namespace {

using testing::partAt;
using testing::randomBox;
using testing::sampledValue;
using testing::uniform;

TEST(SuperquadricSlopes, SlotsAddressTheFourteenValues) {
  PartBox b;
  EXPECT_EQ(&partSlot(b, 0), &b.params.eps1);
  EXPECT_EQ(&partSlot(b, 4), &b.params.a3);
  EXPECT_EQ(&partSlot(b, 7), &b.params.kv);
  EXPECT_EQ(&partSlot(b, 8), &b.params.t);
  EXPECT_EQ(&partSlot(b, 9), &b.placement.tx);
  EXPECT_EQ(&partSlot(b, 12), &b.placement.deg);
  EXPECT_EQ(&partSlot(b, 13), &b.placement.scale);
}

// Central differences at sampled parameter vectors and points lie in the enclosures.
TEST(SuperquadricSlopes, EnclosuresHoldCentralDifferences) {
  std::mt19937_64 rng(3);
  int checked = 0, bounded = 0;
  int all[kPartSlots];
  for (int i = 0; i < kPartSlots; ++i) all[i] = i;
  for (int k = 0; k < 300; ++k) {
    const PartBox box = randomBox(rng, 0.02);
    const PlacedSuperquadric centre = midpointPart(box);
    // A point near the surface of the centre part: a random direction scaled to F = 1.
    Vec3 p = placeToWorld(centre.placement,
                          deformPoint(centre.params, testing::randomPointInBox(rng, centre.params)));
    const double e = 0.01 * uniform(rng, 0.0, 1.0);
    const Interval x{p.x - e, p.x + e}, y{p.y - e, p.y + e}, z{p.z - e, p.z + e};
    Interval d[kPartSlots];
    if (!insideOutsideSlopes(box, x, y, z, all, kPartSlots, d)) continue;
    ++bounded;
    for (int s = 0; s < 8; ++s) {
      double v[kPartSlots];
      for (int i = 0; i < kPartSlots; ++i) {
        const Interval& w = partSlot(box, i);
        v[i] = uniform(rng, w.lo + 0.01 * width(w), w.hi - 0.01 * width(w));
      }
      const Vec3 q{uniform(rng, x.lo, x.hi), uniform(rng, y.lo, y.hi), uniform(rng, z.lo, z.hi)};
      for (int i = 0; i < kPartSlots; ++i) {
        const double h = 1e-5 * width(partSlot(box, i));
        double a[kPartSlots], b[kPartSlots];
        std::copy(v, v + kPartSlots, a);
        std::copy(v, v + kPartSlots, b);
        a[i] -= h;
        b[i] += h;
        const double fd = (partAt(box, b).insideOutside(q) - partAt(box, a).insideOutside(q)) / (2 * h);
        if (!std::isfinite(fd)) continue;
        const double tol = 1e-4 * (1.0 + std::fabs(fd));
        EXPECT_GE(fd, d[i].lo - tol) << "slot " << i << " part " << k;
        EXPECT_LE(fd, d[i].hi + tol) << "slot " << i << " part " << k;
        ++checked;
      }
    }
  }
  EXPECT_GT(bounded, 100);
  EXPECT_GT(checked, 10000);
}

// Where every slope has a sign, F over the box lies between its two signed corners.
TEST(SuperquadricSlopes, SignedSlopesPutTheExtremesAtCorners) {
  std::mt19937_64 rng(5);
  int monotone = 0;
  int all[kPartSlots];
  for (int i = 0; i < kPartSlots; ++i) all[i] = i;
  for (int k = 0; k < 400; ++k) {
    const PartBox box = randomBox(rng, 0.001);
    const PlacedSuperquadric centre = midpointPart(box);
    const Vec3 p = placeToWorld(
        centre.placement, deformPoint(centre.params, testing::randomPointInBox(rng, centre.params)));
    Interval d[kPartSlots];
    if (!insideOutsideSlopes(box, {p.x, p.x}, {p.y, p.y}, {p.z, p.z}, all, kPartSlots, d)) continue;
    double least[kPartSlots], largest[kPartSlots];
    bool signs = true;
    for (int i = 0; i < kPartSlots && signs; ++i) {
      const Interval& w = partSlot(box, i);
      signs = d[i].lo >= 0.0 || d[i].hi <= 0.0;
      least[i] = d[i].lo >= 0.0 ? w.lo : w.hi;
      largest[i] = d[i].lo >= 0.0 ? w.hi : w.lo;
    }
    if (!signs) continue;
    ++monotone;
    const double lo = partAt(box, least).insideOutside(p), hi = partAt(box, largest).insideOutside(p);
    for (int s = 0; s < 64; ++s) {
      const double f = sampledValue(rng, box, s, p);
      EXPECT_GE(f, lo - 1e-12 * (1 + lo)) << k;
      EXPECT_LE(f, hi + 1e-12 * (1 + hi)) << k;
    }
  }
  EXPECT_GT(monotone, 20);
}

// The mean value form about Baumann's centre holds F at sampled parameters (corners and
// interior) of random boxes, at points near the surface; it is at least as tight as the form
// about the midpoint on the side it serves; an unlisted interval value gives the trivial answer.
TEST(SuperquadricSlopes, MeanValueEndsHoldSampledValues) {
  std::mt19937_64 rng(7);
  int bounded = 0, checked = 0, nontrivial = 0;
  int all[kPartSlots];
  for (int i = 0; i < kPartSlots; ++i) all[i] = i;
  for (int k = 0; k < 300; ++k) {
    const PartBox box = randomBox(rng, k % 2 == 0 ? 0.02 : 0.002);
    const PlacedSuperquadric centre = midpointPart(box);
    const Vec3 p = placeToWorld(
        centre.placement, deformPoint(centre.params, testing::randomPointInBox(rng, centre.params)));
    Interval d[kPartSlots];
    if (!insideOutsideSlopes(box, {p.x, p.x}, {p.y, p.y}, {p.z, p.z}, all, kPartSlots, d)) continue;
    ++bounded;
    const double lo = meanValueEnd(box, p, true, all, kPartSlots, d);
    const double hi = meanValueEnd(box, p, false, all, kPartSlots, d);
    ASSERT_FALSE(std::isnan(lo));
    ASSERT_FALSE(std::isnan(hi));
    ASSERT_LE(lo, hi);
    nontrivial += std::isfinite(lo) && std::isfinite(hi);
    // The midpoint form with the same slopes.
    const double fm = centre.insideOutside(p);
    double midLo = fm, midHi = fm;
    for (int i = 0; i < kPartSlots; ++i) {
      const Interval& w = partSlot(box, i);
      const Interval t = mul(d[i], Interval{w.lo - mid(w), w.hi - mid(w)});
      midLo += t.lo;
      midHi += t.hi;
    }
    const double slack = 1e-9 * (1.0 + std::fabs(fm));
    EXPECT_GE(lo, midLo - slack) << k;
    EXPECT_LE(hi, midHi + slack) << k;
    for (int s = 0; s < 64; ++s) {
      const double f = sampledValue(rng, box, s, p);
      EXPECT_GE(f, lo - 1e-12 * (1 + std::fabs(f))) << k;
      EXPECT_LE(f, hi + 1e-12 * (1 + std::fabs(f))) << k;
      ++checked;
    }
    // Slot 0 (eps1) left out while still an interval: no bound.
    EXPECT_EQ(meanValueEnd(box, p, true, all + 1, kPartSlots - 1, d + 1), -INFINITY);
    EXPECT_EQ(meanValueEnd(box, p, false, all + 1, kPartSlots - 1, d + 1), INFINITY);
  }
  EXPECT_GT(bounded, 100);
  EXPECT_GT(nontrivial, 100);
  EXPECT_GT(checked, 6000);
}

TEST(SuperquadricSlopes, UnboundedSlopesAnswerFalse) {
  int slot = 7;  // kv
  PartBox box;
  box.params.kv = {-0.1, 0.1};  // may vanish: the bend's z' = atan(v/u)/kv has no bound here
  Interval d[1];
  EXPECT_FALSE(insideOutsideSlopes(box, {0.5, 0.5}, {0.1, 0.1}, {0.2, 0.2}, &slot, 1, d));
  PartBox taper;
  taper.params.kx = {0.9, 1.0};  // the taper factor kx·z/C + 1 reaches 0 at z = −C
  slot = 5;
  EXPECT_FALSE(insideOutsideSlopes(taper, {0.5, 0.5}, {0.0, 0.0}, {-1.2, -1.0}, &slot, 1, d));
  // A sphere of fuzzy radius: dF/da1 = −2|p|²/a1³ < 0 everywhere but the centre.
  PartBox sphere;
  sphere.params.a1 = {0.9, 1.1};
  slot = 2;
  ASSERT_TRUE(insideOutsideSlopes(sphere, {1.0, 1.0}, {0.0, 0.0}, {0.0, 0.0}, &slot, 1, d));
  EXPECT_LE(d[0].lo, -2.0 / (0.9 * 0.9 * 0.9) + 1e-12);
  EXPECT_GE(d[0].hi, -2.0 / (1.1 * 1.1 * 1.1) - 1e-12);
  EXPECT_LT(d[0].hi, 0.0);
}

}  // namespace
}  // namespace fsdb
