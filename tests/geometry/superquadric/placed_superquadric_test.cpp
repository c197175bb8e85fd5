// Tests for geometry/superquadric/placed_superquadric.h: world points are evaluated by undoing the
// placement and the deformations; validation paths follow the part document.
#include "geometry/superquadric/placed_superquadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geometry/superquadric/deformation.h"
#include "geometry/core/error.h"
#include "tests/geometry/random_superquadric.h"

namespace fsdb {
namespace {

using testing::kPi;
using testing::randomParams;
using testing::randomPointInBox;

double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

Placement randomPlacement(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), angle(-360, 360), logScale(-2, 2);
  Placement p;
  p.translate = {10 * u(rng), 10 * u(rng), 10 * u(rng)};
  do {
    p.axis = {u(rng), u(rng), u(rng)};
  } while (norm(p.axis) < 1e-3);
  p.deg = angle(rng);
  p.scale = std::exp(logScale(rng));
  return p;
}

TEST(PlacedSuperquadric, ValidationPathsFollowThePartDocument) {
  PlacedSuperquadric part;
  EXPECT_NO_THROW(part.validate());
  part.params.kv = 10;
  try {
    part.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "params.kv");
  }
  part = PlacedSuperquadric{};
  part.placement.axis = {0, 0, 0};
  try {
    part.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "transform.rotate.axis");
  }
  part.placement = Placement{};
  part.placement.scale = -2;
  try {
    part.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "transform.scale");
  }
}

TEST(PlacedSuperquadric, PlacedSphereDistanceIsEuclidean) {
  PlacedSuperquadric ball;
  ball.params.a1 = 1.5;
  ball.placement.translate = {1, -2, 3};
  ball.placement.axis = {1, 2, 3};
  ball.placement.deg = 37;
  ball.placement.scale = 2;  // world radius 3
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 w{u(rng), u(rng), u(rng)};
    const double r = distance(w, ball.placement.translate);
    ASSERT_NEAR(ball.pseudoDistance(w), r - 3, 1e-13 * (r + 3));
    ASSERT_NEAR(ball.insideOutside(w), (r / 3) * (r / 3), 1e-13 * (1 + r * r));
  }
  EXPECT_NEAR(ball.pseudoDistance(ball.placement.translate), -3, 1e-15);
}

TEST(PlacedSuperquadric, ToWorldAndToCanonicalAreInverse) {
  std::mt19937_64 rng(31);
  for (int i = 0; i < 2000; ++i) {
    PlacedSuperquadric part{randomParams(rng, /*injectiveBend=*/true), randomPlacement(rng)};
    ASSERT_NO_THROW(part.validate());
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = randomPointInBox(rng, part.params);
      const Vec3 w = part.toWorld(c);
      ASSERT_LT(distance(part.toCanonical(w), c), 1e-11 * std::max(1.0, norm(c)));
      ASSERT_EQ(w, placeToWorld(part.placement, deformPoint(part.params, c)));
      // The placed inside-outside value of a world point is the canonical one of its preimage.
      const double f = insideOutside(part.params, c);
      ASSERT_NEAR(part.insideOutside(w), f, 1e-9 * std::max(1.0, f));
    }
  }
}

TEST(PlacedSuperquadric, SurfaceMapsToTheZeroSet) {
  // Points on the canonical surface, deformed and placed, have F = 1 and distance 0; points
  // pulled in or pushed out radially keep their side.
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> eta(-kPi / 2, kPi / 2), omega(-kPi, kPi);
  auto signedPow = [](double c, double e) { return std::copysign(std::pow(std::fabs(c), e), c); };
  for (int i = 0; i < 2000; ++i) {
    PlacedSuperquadric part{randomParams(rng, /*injectiveBend=*/true), randomPlacement(rng)};
    const auto& q = part.params;
    const double la = eta(rng), lo = omega(rng);
    const double ce = signedPow(std::cos(la), q.eps1);
    const Vec3 onSurface{q.A() * ce * signedPow(std::cos(lo), q.eps2),
                         q.B() * ce * signedPow(std::sin(lo), q.eps2),
                         q.C() * signedPow(std::sin(la), q.eps1)};
    ASSERT_NEAR(part.insideOutside(part.toWorld(onSurface)), 1.0, 1e-8);
    ASSERT_NEAR(part.pseudoDistance(part.toWorld(onSurface)), 0.0,
                1e-9 * part.placement.scale * (1 + norm(onSurface)));
    ASSERT_LT(part.pseudoDistance(part.toWorld(0.9 * onSurface)), 0.0);
    ASSERT_GT(part.pseudoDistance(part.toWorld(1.1 * onSurface)), 0.0);
    ASSERT_LT(part.insideOutside(part.toWorld(0.9 * onSurface)), 1.0);
    ASSERT_GT(part.insideOutside(part.toWorld(1.1 * onSurface)), 1.0);
  }
}

TEST(PlacedSuperquadric, PseudoDistanceIsInWorldUnits) {
  PlacedSuperquadric part;
  part.params.eps1 = 0.5;
  part.params.eps2 = 2;
  part.params.a1 = 2;
  part.params.a3 = 1.5;  // C = 3
  part.placement.scale = 4;
  part.placement.translate = {0, 0, 10};
  // Along the (placed, unrotated) z axis the radial distance is exact: top at z = 10 + 4·3.
  EXPECT_NEAR(part.pseudoDistance({0, 0, 25}), 3, 1e-13);
  EXPECT_NEAR(part.pseudoDistance({0, 0, 10}), -8, 1e-13);  // centre: −scale·min(A, B, C)
}

TEST(PlacedSuperquadric, StaysFiniteOnTheTaperSingularity) {
  PlacedSuperquadric part;
  part.params.kx = -1;  // factor 1 − z/C vanishes at z = C
  part.placement.scale = 3;
  const Vec3 w = part.toWorld({0, 0, 1});
  EXPECT_DOUBLE_EQ(part.insideOutside(w), 1.0);
  const Vec3 beside{w.x + 0.5, w.y, w.z};  // no preimage: "outside"
  EXPECT_EQ(part.insideOutside(beside), std::numeric_limits<double>::max());
  EXPECT_EQ(part.pseudoDistance(beside), std::numeric_limits<double>::max());
}

TEST(PreparedSuperquadric, AgreesBitForBitWithPlacedSuperquadric) {
  std::mt19937_64 rng(123);
  std::uniform_real_distribution<double> u(-8, 8);
  for (int i = 0; i < 500; ++i) {
    PlacedSuperquadric part{randomParams(rng, /*injectiveBend=*/false), randomPlacement(rng)};
    const PreparedSuperquadric prepared(part);
    EXPECT_EQ(prepared.params().kv, part.params.kv);
    for (int j = 0; j < 5; ++j) {
      const Vec3 w{u(rng), u(rng), u(rng)};
      ASSERT_EQ(prepared.toCanonical(w), part.toCanonical(w));
      ASSERT_EQ(prepared.insideOutside(w), part.insideOutside(w));
      ASSERT_EQ(prepared.pseudoDistance(w), part.pseudoDistance(w));
    }
  }
}

TEST(PreparedSuperquadric, ValidatesOnConstruction) {
  PlacedSuperquadric part;
  part.params.eps2 = 5;
  try {
    PreparedSuperquadric prepared(part);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "params.eps2");
  }
}

}  // namespace
}  // namespace fsdb
