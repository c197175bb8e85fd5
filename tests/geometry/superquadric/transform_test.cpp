// Tests for geometry/superquadric/transform.h: Rodrigues rotations, placement (scale, rotate, translate),
// its exact inverse, and validation paths.
#include "geometry/superquadric/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

Vec3 randomVec(std::mt19937_64& rng, double range) {
  std::uniform_real_distribution<double> u(-range, range);
  return {u(rng), u(rng), u(rng)};
}

TEST(Rotation, DefaultIsTheIdentity) {
  const Rotation r;
  EXPECT_EQ(r.apply({1, -2, 3}), (Vec3{1, -2, 3}));
  EXPECT_EQ(r.applyInverse({1, -2, 3}), (Vec3{1, -2, 3}));
}

TEST(Rotation, QuarterTurnsAreExact) {
  const auto z90 = Rotation::fromAxisAngle({0, 0, 1}, 90);
  EXPECT_EQ(z90.apply({1, 0, 0}), (Vec3{0, 1, 0}));
  EXPECT_EQ(z90.apply({0, 1, 0}), (Vec3{-1, 0, 0}));
  EXPECT_EQ(Rotation::fromAxisAngle({1, 0, 0}, 90).apply({0, 1, 0}), (Vec3{0, 0, 1}));
  EXPECT_EQ(Rotation::fromAxisAngle({0, 1, 0}, 90).apply({0, 0, 1}), (Vec3{1, 0, 0}));
  EXPECT_EQ(Rotation::fromAxisAngle({0, 0, 2}, 180).apply({1, 2, 3}), (Vec3{-1, -2, 3}));
  EXPECT_EQ(Rotation::fromAxisAngle({0, 0, 1}, -90).apply({1, 0, 0}), (Vec3{0, -1, 0}));
  EXPECT_EQ(Rotation::fromAxisAngle({0, 0, 1}, 270).apply({1, 0, 0}), (Vec3{0, -1, 0}));
  EXPECT_EQ(Rotation::fromAxisAngle({1, 1, 1}, 360).apply({1, 2, 3}), (Vec3{1, 2, 3}));
  EXPECT_EQ(Rotation::fromAxisAngle({0, 0, 1}, 720 + 90).apply({1, 0, 0}), (Vec3{0, 1, 0}));
}

TEST(Rotation, RodriguesAboutADiagonal) {
  // 120° about (1, 1, 1) permutes the axes cyclically: x -> y -> z -> x.
  const auto r = Rotation::fromAxisAngle({1, 1, 1}, 120);
  EXPECT_LT(distance(r.apply({1, 0, 0}), {0, 1, 0}), 1e-15);
  EXPECT_LT(distance(r.apply({0, 1, 0}), {0, 0, 1}), 1e-15);
  EXPECT_LT(distance(r.apply({0, 0, 1}), {1, 0, 0}), 1e-15);
  // 30° about z, general angle.
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  EXPECT_LT(distance(Rotation::fromAxisAngle({0, 0, 5}, 30).apply({2, 1, 7}),
                     {2 * c - 1 * s, 2 * s + 1 * c, 7}),
            1e-15);
}

TEST(Rotation, IsOrthonormalKeepsItsAxisAndInvertsExactly) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> angle(-720, 720);
  for (int i = 0; i < 3000; ++i) {
    Vec3 axis = randomVec(rng, 1);
    if (norm(axis) < 1e-3) continue;
    const double deg = angle(rng);
    const auto r = Rotation::fromAxisAngle(axis, deg);
    const Vec3 v = randomVec(rng, 10);
    const Vec3 w = r.apply(v);
    ASSERT_NEAR(norm(w), norm(v), 1e-14 * norm(v));
    ASSERT_LT(distance(r.applyInverse(w), v), 1e-14 * norm(v));
    ASSERT_LT(distance(r.apply(axis), axis), 1e-15 * 4);
    // The inverse is the rotation by −deg, and by deg about −axis.
    ASSERT_LT(distance(Rotation::fromAxisAngle(axis, -deg).apply(v), r.applyInverse(v)), 1e-13);
    ASSERT_LT(distance(Rotation::fromAxisAngle(-axis, deg).apply(v), r.applyInverse(v)), 1e-13);
    // Right-handed: (axis × v) points the way v turns for small positive angles.
    const Vec3 vPerp = v - dot(v, axis) / dot(axis, axis) * axis;
    if (norm(vPerp) > 1e-3) {
      const Vec3 turned = Rotation::fromAxisAngle(axis, 1).apply(v) - v;
      ASSERT_GT(dot(turned, cross(axis, v)), 0);
    }
  }
}

TEST(Placement, DefaultsAreTheIdentityAndValid) {
  const Placement p;
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(placeToWorld(p, {1, 2, 3}), (Vec3{1, 2, 3}));
  EXPECT_EQ(placeToLocal(p, {1, 2, 3}), (Vec3{1, 2, 3}));
}

TEST(Placement, ScalesThenRotatesThenTranslates) {
  Placement p;
  p.scale = 2;
  p.axis = {0, 0, 1};
  p.deg = 90;
  p.translate = {1, 2, 3};
  // (1, 0, 0) -> scale (2, 0, 0) -> rotate (0, 2, 0) -> translate (1, 4, 3).
  EXPECT_EQ(placeToWorld(p, {1, 0, 0}), (Vec3{1, 4, 3}));
  EXPECT_EQ(placeToLocal(p, {1, 4, 3}), (Vec3{1, 0, 0}));
  EXPECT_EQ(placeToWorld(p, {0, 0, 0}), p.translate);
}

TEST(PlacementFrame, RoundTripsOnRandomPlacements) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> angle(-360, 360), logScale(-5, 5);
  for (int i = 0; i < 3000; ++i) {
    Placement p;
    p.translate = randomVec(rng, 100);
    p.axis = randomVec(rng, 1);
    p.deg = angle(rng);
    p.scale = std::exp(logScale(rng));
    if (norm(p.axis) == 0) continue;
    ASSERT_NO_THROW(p.validate());
    const PlacementFrame frame(p);
    EXPECT_EQ(frame.scale(), p.scale);
    const Vec3 local = randomVec(rng, 10);
    const Vec3 world = frame.toWorld(local);
    ASSERT_LT(distance(frame.toLocal(world), local), 1e-12 * (1 + norm(p.translate) / p.scale));
    ASSERT_EQ(world, placeToWorld(p, local));
    ASSERT_EQ(frame.toLocal(world), placeToLocal(p, world));
    // Lengths scale by `scale`.
    const Vec3 other = randomVec(rng, 10);
    ASSERT_NEAR(distance(frame.toWorld(other), world), p.scale * distance(other, local),
                1e-12 * (p.scale * distance(other, local) + norm(p.translate)));
  }
}

void expectInvalid(const Placement& p, const std::string& path) {
  try {
    p.validate();
    FAIL() << "expected an error at " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(Placement, ValidationNamesTheBadValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Placement p;
  p.scale = 0;
  expectInvalid(p, "scale");
  p.scale = -1;
  expectInvalid(p, "scale");
  p.scale = nan;
  expectInvalid(p, "scale");
  p.scale = inf;
  expectInvalid(p, "scale");
  p = Placement{};
  p.axis = {0, 0, 0};
  expectInvalid(p, "rotate.axis");
  p.axis = {nan, 0, 1};
  expectInvalid(p, "rotate.axis");
  p = Placement{};
  p.deg = inf;
  expectInvalid(p, "rotate.deg");
  p = Placement{};
  p.translate = {0, nan, 0};
  expectInvalid(p, "translate");
  p = Placement{};
  p.axis = {0, 3, 4};  // any non-zero length is fine
  p.deg = -1e6;
  p.scale = 1e-9;
  EXPECT_NO_THROW(p.validate());
}

}  // namespace
}  // namespace fsdb
