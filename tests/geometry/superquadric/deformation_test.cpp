// Tests for geometry/superquadric/deformation.h: each map against its defining formula, exact inverses on
// thousands of random parameters and points (fixed seeds), curvature near and at zero, and
// the documented behaviour outside the bend's one-to-one domain.
#include "geometry/superquadric/deformation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tests/geometry/random_superquadric.h"
#include "geometry/core/vec3.h"

namespace fsdb {
namespace {

using testing::kPi;
using testing::randomParams;
using testing::randomPointInBox;

double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

SuperquadricParams withSize(double a1, double a2, double a3) {
  SuperquadricParams p;
  p.a1 = a1;
  p.a2 = a2;
  p.a3 = a3;
  return p;
}

TEST(Deformation, ZeroParametersAreTheIdentity) {
  const auto p = withSize(2, 0.5, 3);
  const Vec3 v{0.3, -1.7, 2.9};
  EXPECT_EQ(taper(p, v), v);
  EXPECT_EQ(untaper(p, v), v);
  EXPECT_EQ(twist(p, v), v);
  EXPECT_EQ(untwist(p, v), v);
  EXPECT_EQ(bend(p, v), v);
  EXPECT_EQ(unbend(p, v), v);
  EXPECT_EQ(deformPoint(p, v), v);
  EXPECT_EQ(undeformPoint(p, v), v);
}

TEST(Deformation, TaperMatchesSpec) {
  auto p = withSize(1, 1, 2);  // C = 2
  p.kx = 0.5;
  p.ky = -0.5;
  const Vec3 top = taper(p, {1, 1, 2});  // z/C = 1
  EXPECT_DOUBLE_EQ(top.x, 1.5);
  EXPECT_DOUBLE_EQ(top.y, 0.5);
  EXPECT_DOUBLE_EQ(top.z, 2.0);
  const Vec3 mid = taper(p, {-2, 3, -1});  // z/C = -1/2
  EXPECT_DOUBLE_EQ(mid.x, -2 * 0.75);
  EXPECT_DOUBLE_EQ(mid.y, 3 * 1.25);
  EXPECT_EQ(untaper(p, top), (Vec3{1, 1, 2}));
}

TEST(Deformation, TwistRotatesAboutZByTzOverC) {
  auto p = withSize(1, 1, 2);  // C = 2
  p.t = kPi / 2;
  const Vec3 top = twist(p, {1, 0, 2});  // θ = π/2
  EXPECT_NEAR(top.x, 0, 1e-15);
  EXPECT_NEAR(top.y, 1, 1e-15);
  EXPECT_EQ(top.z, 2);
  const Vec3 bottom = twist(p, {1, 0, -2});  // θ = −π/2
  EXPECT_NEAR(bottom.x, 0, 1e-15);
  EXPECT_NEAR(bottom.y, -1, 1e-15);
  EXPECT_EQ(twist(p, {1, 2, 0}), (Vec3{1, 2, 0}));
  const Vec3 q = twist(p, {0.3, -0.4, 1.1});
  EXPECT_NEAR(std::hypot(q.x, q.y), 0.5, 1e-15);
  EXPECT_NEAR(distance(untwist(p, q), {0.3, -0.4, 1.1}), 0, 1e-15);
}

TEST(Deformation, BendMatchesSolinasEquations) {
  // Solina & Bajcsy 1990 with α = 0 written literally (with its 1/k terms), for curvatures
  // where that form is accurate.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> curvature(-1.0, 1.0), coord(-1.5, 1.5);
  for (int i = 0; i < 5000; ++i) {
    auto p = withSize(1, 1, 1.5);
    p.kv = curvature(rng);
    if (std::fabs(p.kv) < 0.05) continue;
    const Vec3 v{coord(rng), coord(rng), coord(rng)};
    const double k = p.kv, gamma = v.z * k;
    const double R = 1 / k - std::cos(gamma) * (1 / k - v.x);
    const Vec3 literal{v.x + (R - v.x), v.y, std::sin(gamma) * (1 / k - v.x)};
    ASSERT_LT(distance(bend(p, v), literal), 1e-13);
  }
}

TEST(Deformation, BendMapsTheZAxisOntoAnArcOfRadiusOneOverK) {
  auto p = withSize(1, 1, 4);
  p.kv = 0.5;  // radius 2, axis at x = 2
  for (double z : {-4.0, -1.0, 0.0, 0.5, 3.0}) {
    const Vec3 q = bend(p, {0, 0.7, z});
    EXPECT_NEAR(std::hypot(q.x - 2, q.z), 2, 1e-15);
    EXPECT_NEAR(std::atan2(q.z, 2 - q.x) / p.kv, z, 1e-14);  // arc length is z
    EXPECT_EQ(q.y, 0.7);
  }
  // The ends bend towards +x for kv > 0.
  EXPECT_GT(bend(p, {0, 0, 3}).x, 0);
  EXPECT_GT(bend(p, {0, 0, -3}).x, 0);
}

TEST(Deformation, RoundTripsOnRandomParametersAndPoints) {
  std::mt19937_64 rng(2024);
  for (int i = 0; i < 2000; ++i) {
    const auto p = randomParams(rng, /*injectiveBend=*/true);
    ASSERT_NO_THROW(p.validate());
    for (int j = 0; j < 5; ++j) {
      const Vec3 v = randomPointInBox(rng, p);
      const double tol = 1e-12 * std::max(1.0, norm(v));
      ASSERT_LT(distance(untaper(p, taper(p, v)), v), tol);
      ASSERT_LT(distance(untwist(p, twist(p, v)), v), tol);
      ASSERT_LT(distance(unbend(p, bend(p, v)), v), tol);
      const Vec3 d = deformPoint(p, v);
      ASSERT_LT(distance(undeformPoint(p, d), v), tol)
          << "eps " << p.eps1 << " kx " << p.kx << " ky " << p.ky << " t " << p.t << " kv " << p.kv;
      ASSERT_LT(distance(deformPoint(p, undeformPoint(p, d)), d), tol);
    }
  }
}

TEST(Deformation, RoundTripsUpToTheSpecCurvatureLimitInsideTheDomain) {
  // |kv|·C up to 0.95π: the bend is one-to-one on points with kv·x < 1 (after taper and twist).
  std::mt19937_64 rng(99);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto p = randomParams(rng, /*injectiveBend=*/false);
    ASSERT_NO_THROW(p.validate());
    const Vec3 v = randomPointInBox(rng, p);
    const Vec3 beforeBend = twist(p, taper(p, v));
    if (1 - p.kv * beforeBend.x < 1e-3) continue;  // across the bending axis: not invertible
    const double tol = 1e-11 * std::max(1.0, norm(v));
    ASSERT_LT(distance(undeformPoint(p, deformPoint(p, v)), v), tol);
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

TEST(Deformation, TinyAndZeroCurvatureConvergeToTheIdentity) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  for (double k : {0.0, 1e-300, -1e-300, 1e-12, -1e-12, 1e-8, -1e-8, 1e-5}) {
    auto p = withSize(2, 1, 5);
    p.kv = k;
    for (int i = 0; i < 2000; ++i) {
      const Vec3 v{coord(rng), coord(rng), coord(rng)};
      const Vec3 b = bend(p, v);
      // |bend(v) − v| = O(|k|·|v|²): no cancellation error of size 1e-16/|k|.
      ASSERT_LE(distance(b, v), std::fabs(k) * dot(v, v) + 1e-15 * norm(v)) << k;
      ASSERT_LT(distance(unbend(p, b), v), 2e-15 * norm(v)) << k;
      ASSERT_LT(distance(bend(p, unbend(p, v)), v), 2e-15 * norm(v)) << k;
    }
  }
}

TEST(Deformation, DeformOfUndeformIsTheIdentityEverywhere) {
  // Every point has a principal preimage, also outside the part and beyond the bending axis.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> coord(-30.0, 30.0);
  for (int i = 0; i < 3000; ++i) {
    const auto p = randomParams(rng, /*injectiveBend=*/false);
    const Vec3 q{coord(rng), coord(rng), coord(rng)};
    const Vec3 back = deformPoint(p, undeformPoint(p, q));
    ASSERT_LT(distance(back, q), 1e-10 * std::max(1.0, norm(q)))
        << "kx " << p.kx << " ky " << p.ky << " t " << p.t << " kv " << p.kv;
  }
}

TEST(Deformation, UnbendReturnsThePrincipalPreimage) {
  auto p = withSize(1, 1, 1);
  p.kv = 0.5;  // bending axis at x = 2
  // A point beyond the axis (kv·x > 1) folds onto the image of a point on the near side.
  const Vec3 far{3, 0.25, 0.5};
  const Vec3 folded = bend(p, far);
  const Vec3 principal = unbend(p, folded);
  EXPECT_GT(distance(principal, far), 0.1);
  EXPECT_LT(1 - p.kv * principal.x, 1 + 1e-15);
  EXPECT_GT(1 - p.kv * principal.x, 0);
  EXPECT_LE(std::fabs(p.kv * principal.z), kPi);
  EXPECT_LT(distance(bend(p, principal), folded), 1e-14);
  // The bending axis itself unbends to (1/k, y, 0).
  const Vec3 onAxis = unbend(p, {2, -3, 0});
  EXPECT_DOUBLE_EQ(onAxis.x, 2);
  EXPECT_EQ(onAxis.y, -3);
  EXPECT_EQ(onAxis.z, 0);
  // Negative curvature mirrors everything in x.
  auto m = p;
  m.kv = -0.5;
  const Vec3 mb = bend(m, {-0.3, 0.1, 0.9});
  const Vec3 pb = bend(p, {0.3, 0.1, 0.9});
  EXPECT_NEAR(mb.x, -pb.x, 1e-15);
  EXPECT_NEAR(mb.z, pb.z, 1e-15);
}

TEST(Deformation, UntaperOnTheSingularPlane) {
  auto p = withSize(1, 1, 2);
  p.kx = -1;  // factor 1 − z/C vanishes at z = C = 2 (the part's tip)
  EXPECT_EQ(untaper(p, {0, 0.5, 2}).x, 0.0);
  EXPECT_EQ(untaper(p, {0, 0.5, 2}).y, 0.5);
  EXPECT_EQ(untaper(p, {0.1, 0.5, 2}).x, std::numeric_limits<double>::infinity());
  EXPECT_EQ(untaper(p, {-0.1, 0.5, 2}).x, -std::numeric_limits<double>::infinity());
  // Beyond it the factor is negative but the map is still invertible.
  EXPECT_NEAR(distance(untaper(p, taper(p, {0.3, 0.2, 3})), {0.3, 0.2, 3}), 0, 1e-15);
}

TEST(Deformation, BendIsInjectiveOnPart) {
  auto p = withSize(1, 1, 1);  // A = B = 1
  p.kv = 0.7;
  EXPECT_TRUE(bendIsInjectiveOnPart(p));  // 0.7·√2 < 1
  p.kv = -0.75;
  EXPECT_FALSE(bendIsInjectiveOnPart(p));  // 0.75·√2 > 1
  p.kv = 0.3;
  p.kx = 1;
  p.ky = -1;
  EXPECT_TRUE(bendIsInjectiveOnPart(p));  // 0.3·√8 < 1
  p.kv = 0.4;
  EXPECT_FALSE(bendIsInjectiveOnPart(p));  // 0.4·√8 > 1
  p.kv = 0;
  EXPECT_TRUE(bendIsInjectiveOnPart(p));
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// The tapered solid's widest section, against the forward map of its section edge: points
// (A·cos^ε1 η, 0, C·sin^ε1 η) (signed powers) tapered, their largest |X| over A.
TEST(Deformation, TaperedHalfWidthFactorIsTheWidestTaperedSection) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> e(0.05, 4.0), k(-1.0, 1.0);
  const auto signedPow = [](double b, double p) { return std::copysign(std::pow(std::fabs(b), p), b); };
  for (int trial = 0; trial < 200; ++trial) {
    SuperquadricParams p;
    p.eps1 = e(rng);
    p.a1 = 0.7;
    p.a3 = 1.8;
    p.kx = k(rng);
    double widest = 0.0;
    for (int i = 0; i <= 20000; ++i) {
      const double eta = -M_PI / 2 + M_PI * i / 20000;
      const Vec3 q{p.A() * signedPow(std::cos(eta), p.eps1), 0.0, p.C() * signedPow(std::sin(eta), p.eps1)};
      widest = std::max(widest, std::fabs(taper(p, q).x) / p.A());
    }
    const double f = taperedHalfWidthFactor(p.eps1, p.kx);
    EXPECT_LE(widest, f + 1e-12) << p.eps1 << " " << p.kx;
    EXPECT_NEAR(f, widest, 2e-3) << p.eps1 << " " << p.kx;
  }
  EXPECT_EQ(taperedHalfWidthFactor(0.5, 0.0), 1.0);
  EXPECT_EQ(taperedHalfWidthFactor(2.0, 1.0), 1.0);  // a double pyramid's edge falls as the taper rises
  EXPECT_EQ(taperedHalfWidthFactor(3.0, -0.7), 1.0);
  EXPECT_NEAR(taperedHalfWidthFactor(1.0, 1.0), 1.5 * std::sqrt(0.75), 1e-12);  // w = 1/2
  EXPECT_NEAR(taperedHalfWidthFactor(0.01, 0.6), 1.6, 0.01);                     // a box: 1 + |k|
  EXPECT_NEAR(taperedHalfWidthFactor(0.1, -1.0), 1.9075, 1e-4);                  // a sharp cone's base
  // It rises with |k| and falls with ε1: the measures' corners rely on both (descriptors.h).
  for (double eps : {0.05, 0.3, 1.0, 1.7})
    for (double a = 0.0; a < 1.0; a += 0.05) {
      EXPECT_LE(taperedHalfWidthFactor(eps, a), taperedHalfWidthFactor(eps, a + 0.05));
      EXPECT_GE(taperedHalfWidthFactor(eps, a), taperedHalfWidthFactor(eps + 0.2, a));
    }
}

}  // namespace
}  // namespace fsdb
