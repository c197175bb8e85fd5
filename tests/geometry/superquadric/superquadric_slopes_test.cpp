#include "geometry/superquadric/superquadric_slopes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/superquadric/deformation.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/transform.h"
#include "tests/geometry/random_part_box.h"
#include "tests/geometry/random_superquadric.h"

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
// (F(v + h·e_i) − F(v − h·e_i)) / 2h at the point q.
double centralDifference(const PartBox& box, const double (&v)[kPartSlots], int i, double h,
                         const Vec3& q) {
  double a[kPartSlots], b[kPartSlots];
  std::copy(v, v + kPartSlots, a);
  std::copy(v, v + kPartSlots, b);
  a[i] -= h;
  b[i] += h;
  return (partAt(box, b).insideOutside(q) - partAt(box, a).insideOutside(q)) / (2 * h);
}

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
        const double fd = centralDifference(box, v, i, 1e-5 * width(partSlot(box, i)), q);
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

// The inverse bend's z' = (z/u)·φ(kv·z/u), φ(t) = atan(t)/t: its slopes hold central differences
// for strong bends (|kv|·C up to 3, so t runs through 0 and past the extremes of φ' at ±0.8243)
// and boxes from thin to wide, at points inside, near and outside the part.
TEST(SuperquadricSlopes, BendSlopesHoldCentralDifferences) {
  std::mt19937_64 rng(31);
  int checked = 0;
  const int bend[2] = {7, 4};  // kv, and a3 (which sets C)
  for (int k = 0; k < 400; ++k) {
    PlacedSuperquadric centre;
    centre.params.a3 = uniform(rng, 0.5, 3.0);
    centre.params.kv = uniform(rng, -3.0, 3.0) / centre.params.C();
    centre.params.eps1 = uniform(rng, 0.4, 2.5);
    PartBox box = crispPartBox(centre);
    const double spread = k % 2 ? 0.002 : 0.05;
    for (int i : bend) {
      Interval& v = partSlot(box, i);
      v = {v.lo * (1.0 - spread), v.hi * (1.0 + spread)};
      if (v.lo > v.hi) std::swap(v.lo, v.hi);
    }
    if (!(magnitude(box.params.kv) * box.params.a3.hi * box.params.a1.hi < 3.1)) continue;
    const Vec3 p{uniform(rng, -1.5, 1.5), uniform(rng, -1.5, 1.5),
                 uniform(rng, -1.2, 1.2) * centre.params.C()};
    Interval d[2];
    if (!insideOutsideSlopes(box, {p.x, p.x}, {p.y, p.y}, {p.z, p.z}, bend, 2, d)) continue;
    for (int s = 0; s < 6; ++s) {
      double v[kPartSlots];
      for (int i = 0; i < kPartSlots; ++i) {
        const Interval& w = partSlot(box, i);
        v[i] = w.lo == w.hi ? w.lo : uniform(rng, w.lo + 0.01 * width(w), w.hi - 0.01 * width(w));
      }
      for (int j = 0; j < 2; ++j) {
        const int i = bend[j];
        const double fd = centralDifference(box, v, i, 1e-6 * std::max(std::fabs(v[i]), 1e-3), p);
        if (!std::isfinite(fd) || std::fabs(fd) > 1e6) continue;
        const double tol = 1e-4 * (1.0 + std::fabs(fd));
        EXPECT_GE(fd, d[j].lo - tol) << "slot " << i << " case " << k;
        EXPECT_LE(fd, d[j].hi + tol) << "slot " << i << " case " << k;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

// The same form keeps the slope in kv signed where F is monotone in it: at points of a bent
// part's fuzzy band (kv = 0.3 ± 0.015, C = 2) the interval slope of kv used to straddle 0 at
// every point (atan(kv·w)/kv: two large terms that nearly cancel).
TEST(SuperquadricSlopes, BendSlopeKeepsItsSignInTheBand) {
  PlacedSuperquadric centre;
  centre.params.a3 = 2.0;
  centre.params.kv = 0.3;
  PartBox box = crispPartBox(centre);
  box.params.kv = {0.285, 0.315};
  const int slots[1] = {7};
  int signed_ = 0, tried = 0;
  std::mt19937_64 rng(37);
  while (tried < 200) {
    // A point of the band: inside S(θ) for one end of kv and outside for the other.
    const Vec3 p{uniform(rng, -1.5, 1.5), uniform(rng, -1.5, 1.5), uniform(rng, -2.2, 2.2)};
    double lo[kPartSlots], hi[kPartSlots];
    for (int i = 0; i < kPartSlots; ++i) lo[i] = hi[i] = partSlot(box, i).lo;
    hi[7] = 0.315;
    const double fLo = partAt(box, lo).insideOutside(p), fHi = partAt(box, hi).insideOutside(p);
    if ((fLo <= 1.0) == (fHi <= 1.0)) continue;
    ++tried;
    Interval d[1];
    ASSERT_TRUE(insideOutsideSlopes(box, {p.x, p.x}, {p.y, p.y}, {p.z, p.z}, slots, 1, d));
    signed_ += d[0].lo > 0.0 || d[0].hi < 0.0;
  }
  EXPECT_GT(signed_, 150) << signed_ << " of " << tried;
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
