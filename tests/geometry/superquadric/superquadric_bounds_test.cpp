#include "geometry/superquadric/superquadric_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/superquadric/deformation.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"
#include "tests/geometry/random_superquadric.h"

namespace fsdb {
namespace {

using testing::kPi;
constexpr double kMaxFinite = std::numeric_limits<double>::max();

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A random valid crisp part with every deformation and a random placement.
PlacedSuperquadric randomPart(std::mt19937_64& rng) {
  PlacedSuperquadric part;
  part.params = testing::randomParams(rng, rng() % 2 == 0);
  part.placement.translate = {uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)};
  part.placement.axis = {uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, 0.1, 1)};
  part.placement.deg = uniform(rng, -180, 180);
  part.placement.scale = uniform(rng, 0.5, 2);
  return part;
}

// A parameter box around `c` whose relative spreads are up to `w` (w <= 0.5), each drawn
// separately (some parameters stay crisp). The box is kept inside the valid ranges.
PartBox fuzzify(std::mt19937_64& rng, const PlacedSuperquadric& c, double w) {
  const auto spread = [&] { return rng() % 4 == 0 ? 0.0 : w * uniform(rng, 0, 1); };
  const auto relative = [&](double v) {
    const double s = spread();
    return Interval{v * (1 - s), v * (1 + s)};
  };
  const SuperquadricParams& p = c.params;
  PartBox box;
  SuperquadricBox& q = box.params;
  q.eps1 = intersect(relative(p.eps1), {0.0, 4.0});
  q.eps2 = intersect(relative(p.eps2), {0.0, 4.0});
  q.a1 = relative(p.a1);
  q.a2 = relative(p.a2);
  q.a3 = relative(p.a3);
  const auto absolute = [&](double v, double scale) {
    const double s = spread() * scale;
    return Interval{v - s, v + s};
  };
  q.kx = intersect(absolute(p.kx, 1.0), {-1, 1});
  q.ky = intersect(absolute(p.ky, 1.0), {-1, 1});
  const double cHi = q.a1.hi * q.a3.hi;
  const double kvMax = 0.97 * kPi / cHi;  // |kv|·C < π for every C in the box
  const Interval kv = absolute(p.kv, 0.5 * kPi / p.C());  // may straddle 0
  q.kv = {std::clamp(kv.lo, -kvMax, kvMax), std::clamp(kv.hi, -kvMax, kvMax)};
  q.t = absolute(p.t, 2.0);
  const Placement& pl = c.placement;
  const double size = p.a1 * pl.scale;
  PlacementBox& b = box.placement;
  b.tx = absolute(pl.translate.x, size);
  b.ty = absolute(pl.translate.y, size);
  b.tz = absolute(pl.translate.z, size);
  b.axis = pl.axis;
  b.deg = absolute(pl.deg, 90.0);
  b.scale = relative(pl.scale);
  return box;
}

// A value of the interval: an end 30% of the time (the corners matter most), else uniform.
double sample(std::mt19937_64& rng, const Interval& a) {
  const unsigned r = rng() % 10;
  if (r == 0) return a.lo;
  if (r == 1 || r == 2) return a.hi;
  return a.lo + (a.hi - a.lo) * uniform(rng, 0, 1);
}

PlacedSuperquadric samplePart(std::mt19937_64& rng, const PartBox& box) {
  PlacedSuperquadric part;
  const SuperquadricBox& q = box.params;
  part.params = {sample(rng, q.eps1), sample(rng, q.eps2), sample(rng, q.a1),
                 sample(rng, q.a2),   sample(rng, q.a3),   sample(rng, q.kx),
                 sample(rng, q.ky),   sample(rng, q.kv),   sample(rng, q.t)};
  const PlacementBox& b = box.placement;
  part.placement.translate = {sample(rng, b.tx), sample(rng, b.ty), sample(rng, b.tz)};
  part.placement.axis = b.axis;
  part.placement.deg = sample(rng, b.deg);
  part.placement.scale = sample(rng, b.scale);
  return part;
}

struct PointBox {
  Interval x, y, z;
};

// A box near the part: its centre is the image of a canonical point within 1.5 times the
// part's bounding box, its half-widths up to `w` times the part's size.
PointBox randomPointBox(std::mt19937_64& rng, const PlacedSuperquadric& part, double w) {
  const SuperquadricParams& p = part.params;
  const Vec3 canonical = 1.5 * testing::randomPointInBox(rng, p);
  const Vec3 c = part.toWorld(canonical);
  const double size = std::max({p.A(), p.B(), p.C()}) * part.placement.scale;
  const auto half = [&] { return rng() % 5 == 0 ? 0.0 : w * size * uniform(rng, 0, 1); };
  const double hx = half(), hy = half(), hz = half();
  return {{c.x - hx, c.x + hx}, {c.y - hy, c.y + hy}, {c.z - hz, c.z + hz}};
}

Interval bounds(const PartBox& part, const PointBox& box) {
  return insideOutsideBounds(part, box.x, box.y, box.z);
}

// F lies in r up to a relative tolerance of 1e-9 (no outward rounding; see the header).
::testing::AssertionResult encloses(const Interval& r, double f) {
  const double tol = 1e-9 * std::max(1.0, std::fabs(f));
  if (f >= r.lo - tol && f <= r.hi + tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "F = " << f << " outside [" << r.lo << ", " << r.hi << "]";
}

void expectWellFormed(const Interval& r) {
  EXPECT_FALSE(std::isnan(r.lo) || std::isnan(r.hi));
  EXPECT_LE(0.0, r.lo);
  EXPECT_LE(r.lo, r.hi);
  EXPECT_LE(r.hi, kMaxFinite);
}

TEST(SuperquadricBounds, CrispPartBoxHoldsThePartAndOnlyIt) {
  std::mt19937_64 rng(1);
  const PlacedSuperquadric part = randomPart(rng);
  const PartBox box = crispPartBox(part);
  EXPECT_TRUE(contains(box, part));
  PlacedSuperquadric other = part;
  other.params.kv *= 0.5;
  EXPECT_FALSE(contains(box, other));
  other = part;
  other.placement.axis = -1.0 * part.placement.axis;
  EXPECT_FALSE(contains(box, other));
  other = part;
  other.placement.axis = 3.0 * part.placement.axis;  // same direction, other length
  EXPECT_TRUE(contains(box, other));
}

// Soundness: thousands of random parameter boxes and point boxes; crisp parts and points
// sampled inside them (ends favoured) always evaluate inside the enclosure.
TEST(SuperquadricBounds, RandomBoxesEncloseEverySampledPartAndPoint) {
  std::mt19937_64 rng(20261122);
  const double paramSpreads[] = {0.0, 1e-6, 0.05, 0.5};
  const double pointSpreads[] = {0.0, 0.01, 0.1, 0.5};
  int checks = 0, inside = 0, outside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const PlacedSuperquadric centre = randomPart(rng);
    const PartBox box = fuzzify(rng, centre, paramSpreads[trial % 4]);
    const PointBox points = randomPointBox(rng, centre, pointSpreads[(trial / 4) % 4]);
    const Interval r = bounds(box, points);
    expectWellFormed(r);
    for (int s = 0; s < 12; ++s) {
      const PlacedSuperquadric part = samplePart(rng, box);
      ASSERT_NO_THROW(part.validate());
      const Vec3 w{sample(rng, points.x), sample(rng, points.y), sample(rng, points.z)};
      const double f = part.insideOutside(w);
      ASSERT_TRUE(encloses(r, f)) << "trial " << trial << " sample " << s;
      ++checks;
      (f <= 1 ? inside : outside)++;
    }
  }
  EXPECT_EQ(checks, 4000 * 12);
  // The cases are not all on one side of the surface.
  EXPECT_GT(inside, checks / 20);
  EXPECT_GT(outside, checks / 20);
}

// Boxes around the bending axis of strongly bent parts, where the inverse bend has no
// derivative and the enclosure falls back to |z| <= max(π|X|, 2|Z|).
TEST(SuperquadricBounds, BoxesStraddlingTheBendingAxisStaySound) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 1000; ++trial) {
    PlacedSuperquadric centre;
    centre.params = testing::randomParams(rng, false);
    const double k = centre.params.kv;
    const PartBox box = fuzzify(rng, centre, trial % 2 == 0 ? 0.0 : 0.1);
    // Identity placement: the bending axis is {x = 1/k, z = 0}.
    const double h = uniform(rng, 0.0, 0.5) / std::fabs(k);
    const double cx = 1.0 / k + uniform(rng, -0.2, 0.2) / std::fabs(k);
    const double cz = uniform(rng, -0.2, 0.2) / std::fabs(k);
    const PointBox points{{cx - h, cx + h}, {-h, h}, {cz - h, cz + h}};
    const Interval r = bounds(box, points);
    expectWellFormed(r);
    for (int s = 0; s < 10; ++s) {
      const PlacedSuperquadric part = samplePart(rng, box);
      const Vec3 w{sample(rng, points.x), sample(rng, points.y), sample(rng, points.z)};
      ASSERT_TRUE(encloses(r, part.insideOutside(w))) << "trial " << trial;
    }
  }
}

// Tightness: a crisp part and a single point give the crisp value at both ends, for F and G.
TEST(SuperquadricBounds, DegenerateBoxesGiveTheCrispValue) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 3000; ++trial) {
    const PlacedSuperquadric part = randomPart(rng);
    const PartBox box = crispPartBox(part);
    const Vec3 w = part.toWorld(1.5 * testing::randomPointInBox(rng, part.params));
    const Interval x{w.x, w.x}, y{w.y, w.y}, z{w.z, w.z};
    const double f = part.insideOutside(w);
    const Interval r = insideOutsideBounds(box, x, y, z);
    const double tol = 1e-9 * std::max(1.0, f);
    EXPECT_NEAR(r.lo, f, tol) << "trial " << trial;
    EXPECT_NEAR(r.hi, f, tol) << "trial " << trial;
    const double g = homogeneousInsideOutside(part.params, part.toCanonical(w));
    const Interval rg = homogeneousInsideOutsideBounds(box, x, y, z);
    EXPECT_NEAR(rg.lo, g, 1e-9 * std::max(1.0, g)) << "trial " << trial;
    EXPECT_NEAR(rg.hi, g, 1e-9 * std::max(1.0, g)) << "trial " << trial;
  }
}

// The width of the enclosure around a fixed part and point, with every parameter and the
// point box spread by h (relative).
double widthAt(const PlacedSuperquadric& c, const Vec3& w, double h) {
  const SuperquadricParams& p = c.params;
  const auto rel = [h](double v) { return Interval{v * (1 - h), v * (1 + h)}; };
  const auto abso = [h](double v) { return Interval{v - h, v + h}; };
  PartBox box;
  box.params = {rel(p.eps1), rel(p.eps2), rel(p.a1), rel(p.a2), rel(p.a3),
                abso(p.kx),  abso(p.ky),  abso(p.kv), abso(p.t)};
  const Placement& pl = c.placement;
  box.placement = {abso(pl.translate.x), abso(pl.translate.y), abso(pl.translate.z), pl.axis,
                   abso(pl.deg),         rel(pl.scale)};
  return width(insideOutsideBounds(box, abso(w.x), abso(w.y), abso(w.z)));
}

// Convergence order >= 1: halving every spread at least roughly halves the width, for
// points whose canonical coordinates are away from the planes where |.| and fractional
// powers are not smooth.
TEST(SuperquadricBounds, WidthShrinksLinearlyWithTheBoxes) {
  std::mt19937_64 rng(9);
  int tested = 0;
  for (int trial = 0; trial < 400 && tested < 100; ++trial) {
    const PlacedSuperquadric part = randomPart(rng);
    if (!bendIsInjectiveOnPart(part.params)) continue;
    const Vec3 canonical = testing::randomPointInBox(rng, part.params);
    const SuperquadricParams& p = part.params;
    if (std::fabs(canonical.x) < 0.2 * p.A() || std::fabs(canonical.y) < 0.2 * p.B() ||
        std::fabs(canonical.z) < 0.2 * p.C())
      continue;
    const Vec3 w = part.toWorld(canonical);
    const double w1 = widthAt(part, w, 1e-4), w2 = widthAt(part, w, 0.5e-4),
                 w3 = widthAt(part, w, 0.25e-4);
    EXPECT_GT(w1, 0.0);
    EXPECT_GE(w1 / w2, 1.8) << "trial " << trial << " widths " << w1 << " " << w2;
    EXPECT_GE(w2 / w3, 1.8) << "trial " << trial << " widths " << w2 << " " << w3;
    ++tested;
  }
  EXPECT_EQ(tested, 100);
}

PartBox sphereBox(Interval radius, Interval eps) {
  PartBox box;
  box.params.a1 = radius;
  box.params.eps1 = eps;
  box.params.eps2 = eps;
  return box;
}

TEST(SuperquadricBounds, ClassifiesBlocksOfACrispSphere) {
  const PartBox sphere = sphereBox({2, 2}, {1, 1});
  // Inside: the farthest corner of [−0.5, 0.5]³ is at F = 3·0.25/4 = 0.1875.
  const Interval in = insideOutsideBounds(sphere, {-0.5, 0.5}, {-0.5, 0.5}, {-0.5, 0.5});
  EXPECT_DOUBLE_EQ(in.lo, 0.0);
  EXPECT_DOUBLE_EQ(in.hi, 0.1875);
  // Outside: the nearest point of [5, 6] × [0, 1] × [0, 1] is at F = 25/4.
  const Interval out = insideOutsideBounds(sphere, {5, 6}, {0, 1}, {0, 1});
  EXPECT_DOUBLE_EQ(out.lo, 6.25);
  EXPECT_DOUBLE_EQ(out.hi, 38.0 / 4);
  // On the surface: undecided.
  const Interval edge = insideOutsideBounds(sphere, {1.9, 2.1}, {-0.1, 0.1}, {-0.1, 0.1});
  EXPECT_LT(edge.lo, 1.0);
  EXPECT_GT(edge.hi, 1.0);
}

TEST(SuperquadricBounds, ClassifiesBlocksOfAFuzzySphere) {
  const PartBox sphere = sphereBox({1.8, 2.2}, {0.8, 1.2});
  EXPECT_LE(insideOutsideBounds(sphere, {-0.5, 0.5}, {-0.5, 0.5}, {-0.5, 0.5}).hi, 1.0);
  EXPECT_GT(insideOutsideBounds(sphere, {3, 4}, {3, 4}, {3, 4}).lo, 1.0);
  // Between the smallest and the largest sphere: possibly but not necessarily inside.
  const Interval ring = insideOutsideBounds(sphere, {1.95, 2.0}, {0, 0.05}, {0, 0.05});
  EXPECT_LT(ring.lo, 1.0);
  EXPECT_GT(ring.hi, 1.0);
}

TEST(SuperquadricBounds, ClassifiesBlocksOfAFuzzyRotatedRod) {
  // A rod of half-length 5 along z, turned 85° to 95° about x: its axis runs along −y.
  PartBox rod;
  rod.params.a3 = {5, 5};
  rod.placement.axis = {1, 0, 0};
  rod.placement.deg = {85, 95};
  const Interval in = insideOutsideBounds(rod, {-0.05, 0.05}, {-1.55, -1.45}, {-0.05, 0.05});
  EXPECT_LE(in.hi, 1.0);
  const Interval out = insideOutsideBounds(rod, {-0.05, 0.05}, {-0.05, 0.05}, {3.0, 3.1});
  EXPECT_GT(out.lo, 1.0);
}

TEST(SuperquadricBounds, ClassifiesBlocksOfAFuzzyBentTaperedTwistedPart) {
  PlacedSuperquadric part;
  part.params = {0.7, 1.3, 1.0, 0.8, 2.0, 0.4, -0.3, 0.3, 1.2};
  part.placement.translate = {0.5, -0.25, 0.1};
  part.placement.axis = {1, 1, 0};
  part.placement.deg = 30;
  part.placement.scale = 1.5;
  std::mt19937_64 rng(4);
  const PartBox box = fuzzify(rng, part, 0.02);
  const Vec3 centre = part.toWorld({0.1, 0.1, 0.5});  // deep inside the canonical solid
  const double h = 0.02;
  const Interval in = insideOutsideBounds(box, {centre.x - h, centre.x + h},
                                          {centre.y - h, centre.y + h},
                                          {centre.z - h, centre.z + h});
  EXPECT_LE(in.hi, 1.0);
  const Vec3 far = part.toWorld({0.0, 0.0, 4.0});  // twice the half-length beyond the end
  const Interval out = insideOutsideBounds(box, {far.x - h, far.x + h}, {far.y - h, far.y + h},
                                           {far.z - h, far.z + h});
  EXPECT_GT(out.lo, 1.0);
}

TEST(SuperquadricBounds, ExtremeBoxesSaturateWithoutNaN) {
  PartBox box = sphereBox({0.5, 1}, {0.1, 4});
  box.params.kv = {-1, 1};
  box.params.kx = {-1, 1};
  box.params.t = {-100, 100};
  box.placement.deg = {-1e6, 1e6};
  const double big = 1e200;
  for (const Interval& c : {Interval{-big, big}, Interval{big, big}, Interval{1e100, 1e120},
                            Interval{-3, 3}, Interval{0, 0}}) {
    expectWellFormed(insideOutsideBounds(box, c, c, c));
    const Interval g = homogeneousInsideOutsideBounds(box, c, c, c);
    EXPECT_FALSE(std::isnan(g.lo) || std::isnan(g.hi));
    EXPECT_LE(g.lo, g.hi);
  }
  // Far beyond the doubles' range of F: saturated at both ends, like the crisp function.
  const Interval far = insideOutsideBounds(sphereBox({1, 1}, {0.1, 0.1}), {1e100, 1e100},
                                           {0, 0}, {0, 0});
  EXPECT_EQ(far.lo, kMaxFinite);
  EXPECT_EQ(far.hi, kMaxFinite);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

TEST(MidpointPart, InvertsCrispPartBoxAndTakesIntervalMidpoints) {
  PlacedSuperquadric crisp;
  crisp.params = {0.7, 1.3, 2.0, 0.8, 1.5, 0.2, -0.1, 0.05, 0.4};
  crisp.placement = {{1, -2, 3}, {0, 1, 0}, 30, 1.5};
  const PlacedSuperquadric back = midpointPart(crispPartBox(crisp));
  EXPECT_EQ(back.params.eps1, 0.7);
  EXPECT_EQ(back.params.t, 0.4);
  EXPECT_EQ(back.placement.translate.z, 3.0);
  EXPECT_EQ(back.placement.axis.y, 1.0);
  EXPECT_EQ(back.placement.deg, 30.0);
  PartBox box = crispPartBox(crisp);
  box.params.a1 = {1.0, 3.0};
  box.placement.scale = {1.0, 1.2};
  const PlacedSuperquadric m = midpointPart(box);
  EXPECT_EQ(m.params.a1, 2.0);
  EXPECT_DOUBLE_EQ(m.placement.scale, 1.1);
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// missesDeformedHull says "outside for every θ": then every sampled part has F > 1 at every
// sampled point of the box; and far boxes are missed.
TEST(SuperquadricBounds, DeformedHullHoldsEverySampledPart) {
  std::mt19937_64 rng(20261201);
  const double paramSpreads[] = {0.0, 0.05, 0.2};
  const double pointSpreads[] = {0.0, 0.01, 0.1};
  int missed = 0, checks = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const PlacedSuperquadric centre = randomPart(rng);
    const PartBox box = fuzzify(rng, centre, paramSpreads[trial % 3]);
    PointBox points = randomPointBox(rng, centre, pointSpreads[(trial / 3) % 3]);
    // Reach further out than randomPointBox does, where the hull decides.
    const Vec3 shift = centre.placement.translate;
    const double grow = uniform(rng, 1.0, 4.0);
    points.x = {shift.x + grow * (points.x.lo - shift.x), shift.x + grow * (points.x.hi - shift.x)};
    points.y = {shift.y + grow * (points.y.lo - shift.y), shift.y + grow * (points.y.hi - shift.y)};
    points.z = {shift.z + grow * (points.z.lo - shift.z), shift.z + grow * (points.z.hi - shift.z)};
    if (points.x.lo > points.x.hi) std::swap(points.x.lo, points.x.hi);
    if (points.y.lo > points.y.hi) std::swap(points.y.lo, points.y.hi);
    if (points.z.lo > points.z.hi) std::swap(points.z.lo, points.z.hi);
    if (!missesDeformedHull(box, points.x, points.y, points.z)) continue;
    ++missed;
    for (int s = 0; s < 12; ++s) {
      const PlacedSuperquadric part = samplePart(rng, box);
      const Vec3 w{sample(rng, points.x), sample(rng, points.y), sample(rng, points.z)};
      EXPECT_GT(part.insideOutside(w), 1.0) << "trial " << trial;
      ++checks;
    }
  }
  EXPECT_GT(missed, 300);
  // A unit sphere: the hull is the cube of half-edge 1 (no deformation), placed at the origin.
  PartBox sphere;
  EXPECT_TRUE(missesDeformedHull(sphere, {1.01, 1.2}, {0.0, 0.0}, {0.0, 0.0}));
  EXPECT_FALSE(missesDeformedHull(sphere, {0.99, 1.2}, {0.0, 0.0}, {0.0, 0.0}));
}

// Boxes around the bending axis (local (1/kv, y, 0), where the inverse bend's z spans most of a
// turn and the whole-chain enclosure is trivial): what missesDeformedHull excludes there through
// the unbent hull (|z| <= C, |x|, |y| or the twisted radius within the tapered half-lengths)
// holds no sampled part at any sampled point. Sampling favours the corners of both boxes.
TEST(SuperquadricBounds, UnbentHullHoldsEverySampledPartNearTheBendingAxis) {
  std::mt19937_64 rng(20261202);
  int missed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    PlacedSuperquadric centre = randomPart(rng);
    if (std::fabs(centre.params.kv) < 1e-3) continue;
    const PartBox box = fuzzify(rng, centre, trial % 2 == 0 ? 0.02 : 0.1);
    const SuperquadricParams& q = centre.params;
    const Vec3 axis{1.0 / q.kv + uniform(rng, -0.3, 0.3) * q.A(),
                    uniform(rng, -1.5, 1.5) * q.B(), uniform(rng, -0.3, 0.3) * q.C()};
    const Vec3 c = PlacementFrame(centre.placement).toWorld(axis);
    const double size = q.a1 * centre.placement.scale * uniform(rng, 0.0, 0.2);
    const PointBox points{{c.x - size, c.x + size}, {c.y - size, c.y + size},
                          {c.z - size, c.z + size}};
    if (!missesDeformedHull(box, points.x, points.y, points.z)) continue;
    // Missed although the box's centre lies in the bent hull of the centre part (the local box of
    // deformedHalfExtents): the unbent hull decided.
    double e[3];
    deformedHalfExtents(box.params, &e[0], &e[1], &e[2]);
    const Vec3 l = PlacementFrame(centre.placement).toLocal(c);
    if (std::fabs(l.x) <= e[0] && std::fabs(l.y) <= e[1] && std::fabs(l.z) <= e[2]) ++missed;
    for (int s = 0; s < 40; ++s) {
      const PlacedSuperquadric part = samplePart(rng, box);
      const Vec3 w{sample(rng, points.x), sample(rng, points.y), sample(rng, points.z)};
      EXPECT_GT(part.insideOutside(w), 1.0) << "trial " << trial;
    }
  }
  EXPECT_GT(missed, 100) << missed;
}

// A long bent, tapered part at a point on its bending axis (local (1/kv, 0, 0)): the bent hull
// cannot miss it (the bend swings the long part past the axis), the unbent x is about 1/kv = 3.3,
// far beyond A(1 + |kx|) = 1.5. Near such points the inverse bend's z spans most of a turn, a
// taper factor may vanish and the enclosure may say nothing: before the unbent hull such voxels
// of the 14-fuzzy bench part (bench_fuzzy_part_field.cpp) ran their searches out of budget and
// answered u = 1.
TEST(SuperquadricBounds, UnbentHullMissesAPointOnTheBendingAxis) {
  PartBox box;
  box.params.a3 = {4.0, 4.0};  // long enough for the bend to swing the bent hull past the axis
  box.params.kx = {0.4, 0.5};
  box.params.kv = {0.29, 0.31};
  const Interval px{1.0 / 0.3, 1.0 / 0.3}, p0{0.0, 0.0};
  EXPECT_TRUE(missesDeformedHull(box, px, p0, p0));
  std::mt19937_64 rng(7);
  for (int s = 0; s < 2000; ++s)
    EXPECT_GT(samplePart(rng, box).insideOutside({px.lo, 0.0, 0.0}), 1.0);
}

// A twisted part with a fuzzy twist, at a point well off its axis: the radius that the twist
// keeps bounds F from below, where turning the box of (x, y) by an interval angle alone would
// bring a coordinate near 0.
TEST(SuperquadricBounds, TwistKeepsTheDistanceFromTheAxis) {
  PartBox box;
  box.params.a3 = {3.0, 3.0};  // C = 3
  box.params.t = {2.0, 3.0};   // up to 3 rad over the half-length
  const Interval f = insideOutsideBounds(box, {1.2, 1.2}, {1.2, 1.2}, {-2.5, 2.5});
  // r = 1.2·√2 ≈ 1.70: every point is at least that far from the axis of a unit cross-section.
  EXPECT_GT(f.lo, 1.0);
  for (double z : {-2.5, 0.0, 1.0, 2.5})
    for (double t : {2.0, 2.5, 3.0}) {
      PlacedSuperquadric part;
      part.params.a3 = 3.0;
      part.params.t = t;
      EXPECT_GE(part.insideOutside({1.2, 1.2, z}), f.lo * (1 - 1e-12));
    }
}

TEST(SuperquadricBounds, IsTameBoundsMagnitudeAndRejectsNaN) {
  EXPECT_TRUE(isTame({-kTame, kTame}));
  EXPECT_TRUE(isTame({-1.0, 2.0}));
  EXPECT_FALSE(isTame({-1.0, 2.0 * kTame}));
  EXPECT_FALSE(isTame({-2.0 * kTame, 0.0}));
  EXPECT_FALSE(isTame({std::nan(""), 0.0}));
  EXPECT_FALSE(isTame({0.0, std::numeric_limits<double>::infinity()}));
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// The turn's enclosure holds every sampled point turned by every sampled angle, narrow and wide.
TEST(TurnEnclosure, HoldsSampledTurns) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double x0 = 4 * u(rng) - 2, y0 = 4 * u(rng) - 2, a0 = 8 * u(rng) - 4;
    const Interval xs{x0, x0 + u(rng)}, ys{y0, y0 + u(rng)}, theta{a0, a0 + (k % 2 ? 0.1 : 4.0) * u(rng)};
    Interval x = xs, y = ys;
    turnEnclosure(theta, &x, &y);
    for (int s = 0; s < 50; ++s) {
      const double px = xs.lo + u(rng) * width(xs), py = ys.lo + u(rng) * width(ys);
      const double t = theta.lo + u(rng) * width(theta);
      const double tx = px * std::cos(t) - py * std::sin(t), ty = px * std::sin(t) + py * std::cos(t);
      EXPECT_GE(tx, x.lo - 1e-12) << k;
      EXPECT_LE(tx, x.hi + 1e-12) << k;
      EXPECT_GE(ty, y.lo - 1e-12) << k;
      EXPECT_LE(ty, y.hi + 1e-12) << k;
    }
  }
}

}  // namespace
}  // namespace fsdb
