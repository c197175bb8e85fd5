// Tests for geometry/superquadric/superquadric_volume.h: closed forms against known solids and limits, and
// against counting grid points with F <= 1 (canonical, tapered, and twisted + bent + placed
// parts in world space, the last by undoing the deformations: no Jacobians involved).
#include "geometry/superquadric/superquadric_volume.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/superquadric/deformation.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "tests/geometry/random_superquadric.h"

namespace fsdb {
namespace {

using testing::makeParams;

constexpr double kPi = 3.14159265358979323846;

// Volume of {p in box : inside(p)} by counting the centres of an n·n·n grid of cells.
double gridVolume(const Vec3& lo, const Vec3& hi, int n,
                  const std::function<bool(const Vec3&)>& inside) {
  const Vec3 h = (hi - lo) / n;
  long count = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3 p{lo.x + (i + 0.5) * h.x, lo.y + (j + 0.5) * h.y, lo.z + (k + 0.5) * h.z};
        count += inside(p) ? 1 : 0;
      }
    }
  }
  return count * h.x * h.y * h.z;
}

// The canonical solid is symmetric in each coordinate: count one octant.
double canonicalGridVolume(const SuperquadricParams& q, int n) {
  return 8 * gridVolume({0, 0, 0}, {q.A(), q.B(), q.C()}, n,
                        [&](const Vec3& p) { return insideOutside(q, p) <= 1.0; });
}

TEST(BetaFunction, KnownValues) {
  EXPECT_NEAR(betaFunction(1, 1), 1.0, 1e-15);
  EXPECT_NEAR(betaFunction(0.5, 0.5), kPi, 1e-14);
  EXPECT_NEAR(betaFunction(2, 3), 1.0 / 12, 1e-15);
  EXPECT_NEAR(betaFunction(1.5, 1), 2.0 / 3, 1e-15);
  EXPECT_NEAR(betaFunction(3, 2), betaFunction(2, 3), 1e-16);
  // Tiny arguments: β(a, a) ~ 2/a, while Γ(a)² alone would overflow for a = 1e-200.
  EXPECT_NEAR(betaFunction(1e-200, 1e-200) * 1e-200, 2.0, 1e-12);
  EXPECT_TRUE(std::isfinite(betaFunction(1e-300, 1.0)));
}

TEST(CanonicalVolume, SphereAndEllipsoid) {
  EXPECT_NEAR(canonicalVolume(makeParams(1, 1, 2, 1, 1)), 4.0 / 3 * kPi * 8, 1e-12);
  const auto e = makeParams(1, 1, 2, 0.5, 1.5);  // A = 2, B = 1, C = 3
  EXPECT_NEAR(canonicalVolume(e), 4.0 / 3 * kPi * 2 * 1 * 3, 1e-12);
}

TEST(CanonicalVolume, OctahedronIsFourThirdsABC) {
  // eps1 = eps2 = 2: |x|/A + |y|/B + |z|/C <= 1.
  EXPECT_NEAR(canonicalVolume(makeParams(2, 2, 2, 0.5, 1.5)), 4.0 / 3 * 2 * 1 * 3, 1e-12);
}

TEST(CanonicalVolume, BoxAndCylinderLimits) {
  const double A = 2, B = 1, C = 3;
  const double box = canonicalVolume(makeParams(1e-4, 1e-4, 2, 0.5, 1.5));
  EXPECT_NEAR(box / (8 * A * B * C), 1.0, 1e-3);
  const double cylinder = canonicalVolume(makeParams(1e-4, 1, 2, 0.5, 1.5));
  EXPECT_NEAR(cylinder / (2 * kPi * A * B * C), 1.0, 1e-3);
  // And monotone approach from below: rounder shapes are smaller.
  EXPECT_LT(canonicalVolume(makeParams(0.1, 0.1, 2, 0.5, 1.5)), box);
}

TEST(CanonicalVolume, MatchesGridIntegrationOfInsideOutside) {
  const double pairs[][2] = {{0.5, 0.5}, {1, 1},   {1.5, 0.7}, {2, 2},
                             {0.3, 1},   {3, 0.2}, {0.1, 3.5}};
  for (const auto& e : pairs) {
    const auto q = makeParams(e[0], e[1], 1.5, 0.8, 1.3);
    const double exact = canonicalVolume(q);
    const double counted = canonicalGridVolume(q, 100);
    EXPECT_NEAR(counted / exact, 1.0, 0.01) << "eps1 " << e[0] << " eps2 " << e[1];
  }
}

TEST(TaperVolumeFactor, KnownValues) {
  auto sphere = makeParams(1, 1, 1, 1, 1);
  EXPECT_EQ(taperVolumeFactor(sphere), 1.0);
  sphere.kx = 0.5;  // a single taper adds nothing: the linear term integrates to zero
  EXPECT_EQ(taperVolumeFactor(sphere), 1.0);
  sphere.ky = -0.8;
  EXPECT_NEAR(taperVolumeFactor(sphere), 1 - 0.4 / 5, 1e-15);  // <z²>/C² = 1/5 for a ball
  auto cylinder = makeParams(1e-6, 1, 1, 1, 1);
  cylinder.kx = cylinder.ky = 1;
  EXPECT_NEAR(taperVolumeFactor(cylinder), 1 + 1.0 / 3, 1e-5);  // z uniform: <z²>/C² = 1/3
  EXPECT_NEAR(superquadricVolume(cylinder), canonicalVolume(cylinder) * 4.0 / 3, 1e-5);
}

TEST(TaperVolumeFactor, MatchesGridIntegrationOfTaperedParts) {
  struct Case {
    double e1, e2, kx, ky;
  } cases[] = {{1, 1, 0.8, 0.6},
               {0.5, 0.5, -1, 1},
               {1.5, 0.7, 1, 1},
               {0.3, 1, -0.7, -0.9},
               {2, 2, 0.9, -0.5}};
  for (const auto& c : cases) {
    auto q = makeParams(c.e1, c.e2, 1.2, 1.0, 1.5);
    q.kx = c.kx;
    q.ky = c.ky;
    // The tapered part is symmetric in x and in y: count the quarter x, y >= 0.
    const double counted =
        4 * gridVolume({0, 0, -q.C()},
                       {q.A() * (1 + std::fabs(q.kx)), q.B() * (1 + std::fabs(q.ky)), q.C()}, 110,
                       [&](const Vec3& p) { return insideOutside(q, untaper(q, p)) <= 1.0; });
    EXPECT_NEAR(counted / superquadricVolume(q), 1.0, 0.01)
        << c.e1 << " " << c.e2 << " " << c.kx << " " << c.ky;
  }
}

// World-space bounding box of a placed part: the image of the canonical box's surface bounds
// the image of the solid (the deformation is one-to-one), padded by 2%.
void worldBounds(const PlacedSuperquadric& part, Vec3* lo, Vec3* hi) {
  const auto& q = part.params;
  const int m = 40;
  *lo = Vec3{1e300, 1e300, 1e300};
  *hi = -*lo;
  for (int face = 0; face < 6; ++face) {
    for (int i = 0; i <= m; ++i) {
      for (int j = 0; j <= m; ++j) {
        const double u = -1 + 2.0 * i / m, v = -1 + 2.0 * j / m, w = face % 2 ? 1 : -1;
        const Vec3 unit = face < 2 ? Vec3{w, u, v} : face < 4 ? Vec3{u, w, v} : Vec3{u, v, w};
        const Vec3 p = part.toWorld({q.A() * unit.x, q.B() * unit.y, q.C() * unit.z});
        *lo = {std::min(lo->x, p.x), std::min(lo->y, p.y), std::min(lo->z, p.z)};
        *hi = {std::max(hi->x, p.x), std::max(hi->y, p.y), std::max(hi->z, p.z)};
      }
    }
  }
  const Vec3 pad = 0.02 * (*hi - *lo);
  *lo = *lo - pad;
  *hi = *hi + pad;
}

TEST(SuperquadricVolume, TwistAndBendPreserveVolume) {
  struct Case {
    double e1, e2, kx, ky, t, kv;
  } cases[] = {
      {1, 1, 0, 0, 2.5, 0.4},           // twisted, bent ellipsoid
      {0.3, 0.3, 0.5, -0.4, 1, -0.35},  // near-box, all deformations
      {1.5, 0.7, 1, 1, -3, 0.3},        // pinched, strongly tapered
      {0.5, 2, -0.6, 0, 0, 0.45},       // bend and taper only
  };
  for (const auto& c : cases) {
    PlacedSuperquadric part;
    part.params = makeParams(c.e1, c.e2, 1.0, 0.7, 2.0);  // A = 1, B = 0.7, C = 2
    part.params.kx = c.kx;
    part.params.ky = c.ky;
    part.params.t = c.t;
    part.params.kv = c.kv;
    ASSERT_NO_THROW(part.params.validate());
    ASSERT_TRUE(bendIsInjectiveOnPart(part.params));
    part.placement.translate = {3, -1, 2};
    part.placement.axis = {1, -2, 0.5};
    part.placement.deg = 47;
    part.placement.scale = 1.7;
    Vec3 lo, hi;
    worldBounds(part, &lo, &hi);
    const double counted =
        gridVolume(lo, hi, 110, [&](const Vec3& w) { return part.insideOutside(w) <= 1.0; });
    EXPECT_NEAR(counted / placedVolume(part), 1.0, 0.01)
        << c.e1 << " " << c.e2 << " " << c.kx << " " << c.ky << " " << c.t << " " << c.kv;
  }
}

TEST(SuperquadricVolume, IsCanonicalTimesTaperAndPlacedScalesCubically) {
  auto q = makeParams(0.7, 1.3, 2, 0.6, 1.1);
  q.kx = 0.3;
  q.ky = 0.9;
  q.t = 4;
  q.kv = 0.1;
  EXPECT_DOUBLE_EQ(superquadricVolume(q), canonicalVolume(q) * taperVolumeFactor(q));
  PlacedSuperquadric part{q, Placement{}};
  EXPECT_DOUBLE_EQ(placedVolume(part), superquadricVolume(q));
  part.placement.scale = 3;
  part.placement.deg = 80;
  part.placement.translate = {5, 5, 5};
  EXPECT_NEAR(placedVolume(part), 27 * superquadricVolume(q), 1e-12 * placedVolume(part));
}

}  // namespace
}  // namespace fsdb

