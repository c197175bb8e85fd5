// Tests for geometry/superquadric/superquadric.h: parameter validation, the canonical inside-outside
// function F (against docs/api.md §2 written out literally and against Barr's parametric surface),
// its homogeneous form G, and the radial pseudo distance.
#include "geometry/superquadric/superquadric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "tests/geometry/random_superquadric.h"
#include "geometry/core/error.h"

namespace fsdb {
namespace {

using testing::makeParams;

constexpr double kPi = 3.14159265358979323846;

// docs/api.md §2 verbatim, for moderate exponents where the literal form cannot overflow.
double literalF(const SuperquadricParams& q, const Vec3& p) {
  const double e1 = q.eps1, e2 = q.eps2;
  return std::pow(
             std::pow(std::fabs(p.x) / q.A(), 2 / e2) + std::pow(std::fabs(p.y) / q.B(), 2 / e2),
             e2 / e1) +
         std::pow(std::fabs(p.z) / q.C(), 2 / e1);
}

// sgn(c)|c|^e: Barr's signed power for the parametric surface.
double signedPow(double c, double e) { return std::copysign(std::pow(std::fabs(c), e), c); }

// A point on the surface from Barr's parametrisation, latitude eta, longitude omega.
Vec3 surfacePoint(const SuperquadricParams& q, double eta, double omega) {
  const double ce = signedPow(std::cos(eta), q.eps1);
  return {q.A() * ce * signedPow(std::cos(omega), q.eps2),
          q.B() * ce * signedPow(std::sin(omega), q.eps2),
          q.C() * signedPow(std::sin(eta), q.eps1)};
}

void expectInvalid(const SuperquadricParams& p, const std::string& path, const std::string& range) {
  try {
    p.validate();
    FAIL() << "expected an error for " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
  }
}

TEST(SuperquadricParams, DefaultsAreAValidUnitSphere) {
  SuperquadricParams p;
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(p.A(), 1.0);
  EXPECT_EQ(p.B(), 1.0);
  EXPECT_EQ(p.C(), 1.0);
}

TEST(SuperquadricParams, HalfLengthsFollowSpec) {
  const auto p = makeParams(1, 1, 2, 0.5, 3);
  EXPECT_DOUBLE_EQ(p.A(), 2.0);
  EXPECT_DOUBLE_EQ(p.B(), 1.0);
  EXPECT_DOUBLE_EQ(p.C(), 6.0);
}

TEST(SuperquadricParams, AcceptsRangeBoundaries) {
  auto p = makeParams(4, 4, 1, 1, 1);
  p.kx = 1;
  p.ky = -1;
  p.kv = 0.999 * kPi;  // C = 1
  p.t = -20;
  EXPECT_NO_THROW(p.validate());
  p.eps1 = p.eps2 = 1e-6;
  EXPECT_NO_THROW(p.validate());
}

TEST(SuperquadricParams, RejectsEachParameterWithItsNameAndRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, -1.0, 4.0000001, nan, inf}) {
    auto p = SuperquadricParams{};
    p.eps1 = bad;
    expectInvalid(p, "eps1", "(0, 4]");
    p = SuperquadricParams{};
    p.eps2 = bad;
    expectInvalid(p, "eps2", "(0, 4]");
  }
  for (double bad : {0.0, -2.0, nan, inf}) {
    auto p = SuperquadricParams{};
    p.a1 = bad;
    expectInvalid(p, "a1", "> 0");
    p = SuperquadricParams{};
    p.a2 = bad;
    expectInvalid(p, "a2", "> 0");
    p = SuperquadricParams{};
    p.a3 = bad;
    expectInvalid(p, "a3", "> 0");
  }
  for (double bad : {1.0000001, -1.5, nan}) {
    auto p = SuperquadricParams{};
    p.kx = bad;
    expectInvalid(p, "kx", "[-1, 1]");
    p = SuperquadricParams{};
    p.ky = bad;
    expectInvalid(p, "ky", "[-1, 1]");
  }
  for (double bad : {kPi / 3.0, -kPi / 3.0, 10.0, nan}) {  // C = 3
    auto p = makeParams(1, 1, 1, 1, 3);
    p.kv = bad;
    expectInvalid(p, "kv", "|kv|·C < π");
  }
  for (double bad : {inf, nan}) {
    auto p = SuperquadricParams{};
    p.t = bad;
    expectInvalid(p, "t", "finite");
  }
}

TEST(SuperquadricParams, RejectsHalfLengthsThatLeaveTheDoubles) {
  auto p = makeParams(1, 1, 1e200, 1e200, 1);
  expectInvalid(p, "a2", "B = a1·a2");
  p = makeParams(1, 1, 1e-200, 1, 1e-200);
  expectInvalid(p, "a3", "C = a1·a3");
}

TEST(SuperquadricParams, MessageQuotesTheValue) {
  auto p = SuperquadricParams{};
  p.eps1 = 4.5;
  try {
    p.validate();
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("got 4.5"), std::string::npos) << e.what();
  }
}

TEST(InsideOutside, MatchesTheSpecFormula) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> eps(0.3, 4.0), size(0.2, 5.0), coord(-6.0, 6.0);
  for (int i = 0; i < 5000; ++i) {
    const auto q = makeParams(eps(rng), eps(rng), size(rng), size(rng), size(rng));
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    const double expected = literalF(q, p);
    ASSERT_NEAR(insideOutside(q, p), expected, 1e-12 * std::max(1.0, expected));
  }
}

TEST(InsideOutside, KnownValues) {
  const auto cube = makeParams(1, 1, 2, 1, 1);  // A = B = C = 2, octahedron-like sections
  EXPECT_DOUBLE_EQ(insideOutside(cube, {2, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(insideOutside(cube, {0, -2, 0}), 1.0);
  EXPECT_DOUBLE_EQ(insideOutside(cube, {0, 0, 2}), 1.0);
  EXPECT_DOUBLE_EQ(insideOutside(cube, {2, 2, 2}), 3.0);  // (1 + 1)^1 + 1
  EXPECT_DOUBLE_EQ(insideOutside(cube, {4, 0, 0}), 4.0);
  const auto pinched = makeParams(0.5, 1, 1, 1, 1);  // 2/eps1 = 4
  EXPECT_DOUBLE_EQ(insideOutside(pinched, {0, 0, 2}), 16.0);
  EXPECT_EQ(insideOutside(cube, {0, 0, 0}), 0.0);
}

TEST(InsideOutside, ParametricSurfacePointsHaveFEqualOne) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> eps(0.05, 4.0), size(0.2, 5.0), eta(-kPi / 2, kPi / 2),
      omega(-kPi, kPi);
  for (int i = 0; i < 5000; ++i) {
    const auto q = makeParams(eps(rng), eps(rng), size(rng), size(rng), size(rng));
    const Vec3 s = surfacePoint(q, eta(rng), omega(rng));
    ASSERT_NEAR(insideOutside(q, s), 1.0, 1e-9) << q.eps1 << " " << q.eps2;
    ASSERT_NEAR(homogeneousInsideOutside(q, s), 1.0, 1e-12);
    ASSERT_NEAR(pseudoDistance(q, s), 0.0, 1e-12 * norm(s) + 1e-300);
  }
}

TEST(HomogeneousInsideOutside, IsDegreeOneHomogeneousAndZeroAtTheOrigin) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> eps(0.02, 4.0), size(0.1, 10.0), coord(-3.0, 3.0),
      logLambda(-30.0, 30.0);
  for (int i = 0; i < 5000; ++i) {
    const auto q = makeParams(eps(rng), eps(rng), size(rng), size(rng), size(rng));
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    const double lambda = std::exp(logLambda(rng));
    const double g = homogeneousInsideOutside(q, p);
    ASSERT_NEAR(homogeneousInsideOutside(q, lambda * p), lambda * g, 1e-13 * lambda * g);
    // And G^(2/eps1) is F.
    ASSERT_NEAR(std::pow(g, 2 / q.eps1), insideOutside(q, p),
                1e-12 * std::max(1.0, insideOutside(q, p)));
  }
  EXPECT_EQ(homogeneousInsideOutside(makeParams(0.02, 0.02, 1, 1, 1), {0, 0, 0}), 0.0);
}

TEST(HomogeneousInsideOutside, SmallExponentsDoNotOverflow) {
  // eps = 0.02 gives exponents 2/eps = 100: (3/1)^100 alone is 5e47, and (1e5)^100 overflows.
  const auto box = makeParams(0.02, 0.02, 1, 1, 1);
  EXPECT_NEAR(homogeneousInsideOutside(box, {1e5, 1e5, 1e5}), 1e5 * std::pow(3.0, 0.01),
              1e-9 * 1e5);
  EXPECT_NEAR(homogeneousInsideOutside(box, {3, 0, 0}), 3.0, 1e-15);
  EXPECT_EQ(insideOutside(box, {1e5, 0, 0}), std::numeric_limits<double>::max());  // saturated
  EXPECT_NEAR(insideOutside(box, {0.5, 0.5, 0.5}), std::pow(3.0 * std::pow(0.5, 100), 1.0), 1e-40);
}

TEST(InsideOutside, NoNanOrInfForExtremeExponentsAndCoordinates) {
  const double eps[] = {0.02, 0.1, 1, 2, 4};
  const double coords[] = {0.0, 1e-300, -1e-300, 1e-12, 0.7, -1.0, 1.0, 3.0, -1e6, 1e150, -1e300};
  for (double e1 : eps) {
    for (double e2 : eps) {
      const auto q = makeParams(e1, e2, 1.5, 0.5, 2);
      for (double x : coords) {
        for (double y : coords) {
          for (double z : coords) {
            const Vec3 p{x, y, z};
            const double f = insideOutside(q, p);
            const double d = pseudoDistance(q, p);
            ASSERT_TRUE(std::isfinite(f)) << e1 << " " << e2 << " " << x << " " << y << " " << z;
            ASSERT_TRUE(std::isfinite(d)) << e1 << " " << e2 << " " << x << " " << y << " " << z;
            ASSERT_GE(f, 0.0);
            // Consistent verdicts: inside by F iff inside by d, off the surface itself (the
            // grid has points such as z = C exactly, where rounding may go either way).
            if (std::fabs(homogeneousInsideOutside(q, p) - 1.0) > 1e-12) {
              ASSERT_EQ(f <= 1.0, d <= 0.0) << e1 << " " << e2 << " " << x << " " << y << " " << z;
            }
            if (std::fabs(x) <= 1e150 && std::fabs(y) <= 1e150 && std::fabs(z) <= 1e150) {
              ASSERT_TRUE(std::isfinite(homogeneousInsideOutside(q, p)));
            }
          }
        }
      }
    }
  }
}

TEST(PseudoDistance, IsExactlyRadialDistanceForSpheres) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> radius(0.01, 100.0), coord(-200.0, 200.0);
  for (int i = 0; i < 5000; ++i) {
    const double r = radius(rng);
    const auto sphere = makeParams(1, 1, r, 1, 1);
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    ASSERT_NEAR(pseudoDistance(sphere, p), norm(p) - r, 4e-16 * (norm(p) + r));
  }
  const auto sphere = makeParams(1, 1, 2.5, 1, 1);
  EXPECT_DOUBLE_EQ(pseudoDistance(sphere, {0, 0, 0}), -2.5);
  EXPECT_DOUBLE_EQ(pseudoDistance(sphere, {0, 0, 2.5}), 0.0);
  EXPECT_DOUBLE_EQ(pseudoDistance(sphere, {3, 4, 0}), 2.5);
}

TEST(PseudoDistance, SignAgreesWithInsideOutside) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> eps(0.02, 4.0), size(0.2, 5.0), coord(-6.0, 6.0);
  int inside = 0, outside = 0;
  for (int i = 0; i < 20000; ++i) {
    const auto q = makeParams(eps(rng), eps(rng), size(rng), size(rng), size(rng));
    const Vec3 p{coord(rng), coord(rng), coord(rng)};
    const double g = homogeneousInsideOutside(q, p);
    if (std::fabs(g - 1.0) < 1e-12) continue;  // rounding may disagree on the surface itself
    const double d = pseudoDistance(q, p);
    ASSERT_EQ(insideOutside(q, p) <= 1.0, d <= 0.0);
    (d <= 0.0 ? inside : outside)++;
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

TEST(PseudoDistance, AtTheCentreIsMinusTheShortestHalfLength) {
  EXPECT_DOUBLE_EQ(pseudoDistance(makeParams(0.3, 2, 2, 3, 0.25), {0, 0, 0}), -0.5);
  EXPECT_DOUBLE_EQ(pseudoDistance(makeParams(1, 1, 2, 0.5, 3), {0, 0, 0}), -1.0);
}

TEST(PseudoDistance, AlongAnAxisIsTheAxialDistance) {
  // Along a principal axis the radial distance is exact for any exponents.
  const auto q = makeParams(0.3, 2.5, 2, 1.5, 0.5);  // A = 2, B = 3, C = 1
  EXPECT_NEAR(pseudoDistance(q, {5, 0, 0}), 3.0, 1e-15);
  EXPECT_NEAR(pseudoDistance(q, {0, -1, 0}), -2.0, 1e-15);
  EXPECT_NEAR(pseudoDistance(q, {0, 0, 0.25}), -0.75, 1e-15);
}

}  // namespace
}  // namespace fsdb
