#include "geometry/superquadric/superquadric_extent.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "tests/geometry/random_part_box.h"

namespace fsdb {
namespace {

using testing::randomBox;
using testing::sampledPart;
using testing::uniform;

constexpr double kPi = 3.14159265358979323846;

double signedPower(double v, double e) { return std::copysign(std::pow(std::fabs(v), e), v); }

// Points of the part's surface (the parametric form of the canonical superquadric, deformed and
// placed) on an n × 2n grid of angles, and their box.
void surfaceBox(const PlacedSuperquadric& part, int n, Vec3* lo, Vec3* hi) {
  const SuperquadricParams& s = part.params;
  *lo = {INFINITY, INFINITY, INFINITY};
  *hi = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i <= n; ++i) {
    const double eta = -0.5 * kPi + kPi * i / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double omega = -kPi + kPi * j / n;
      const double ce = signedPower(std::cos(eta), s.eps1);
      const Vec3 w = part.toWorld({s.A() * ce * signedPower(std::cos(omega), s.eps2),
                                   s.B() * ce * signedPower(std::sin(omega), s.eps2),
                                   s.C() * signedPower(std::sin(eta), s.eps1)});
      *lo = componentMin(*lo, w);
      *hi = componentMax(*hi, w);
    }
  }
}

void expectHolds(const Vec3& lo, const Vec3& hi, const Vec3& a, const Vec3& b) {
  const double slack = 1e-9 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1.0});
  EXPECT_LE(lo.x, a.x + slack);
  EXPECT_LE(lo.y, a.y + slack);
  EXPECT_LE(lo.z, a.z + slack);
  EXPECT_GE(hi.x, b.x - slack);
  EXPECT_GE(hi.y, b.y - slack);
  EXPECT_GE(hi.z, b.z - slack);
}

// Sound: the surface of every sampled member (corners and inner θ) of random boxes lies in the
// box, including bends through 0 and twists over most of a turn.
TEST(PartExtent, HoldsEverySampledMembersSurface) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 60; ++k) {
    PartBox box = randomBox(rng, k < 30 ? 0.05 : 0.3);
    if (k % 3 == 0) box.params.kv = {-0.1 / mid(box.params.a1) / mid(box.params.a3),
                                     0.4 / box.params.a1.hi / box.params.a3.hi};
    if (k % 4 == 0) box.params.t = {0.0, uniform(rng, 1.0, 5.0)};
    Vec3 lo, hi;
    partExtent(box, &lo, &hi);
    for (int s = 0; s < 24; ++s) {
      Vec3 a, b;
      surfaceBox(sampledPart(rng, box, s), 24, &a, &b);
      SCOPED_TRACE(k);
      expectHolds(lo, hi, a, b);
    }
  }
}

// Tight: for a crisp part the box is the surface's extent to within a few finest cells' images.
TEST(PartExtent, CrispPartsBoxIsTheirExtent) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 30; ++k) {
    const PlacedSuperquadric part = sampledPart(rng, randomBox(rng, 0.0), 0);
    Vec3 lo, hi, a, b;
    partExtent(crispPartBox(part), &lo, &hi);
    surfaceBox(part, 96, &a, &b);
    expectHolds(lo, hi, a, b);
    const Vec3 box = hi - lo, seen = b - a;
    const double longest = std::max({seen.x, seen.y, seen.z});
    EXPECT_LE(box.x - seen.x, 0.06 * longest) << k;
    EXPECT_LE(box.y - seen.y, 0.06 * longest) << k;
    EXPECT_LE(box.z - seen.z, 0.06 * longest) << k;
  }
}

// A box that runs out of cells is still sound.
TEST(PartExtent, ABudgetThatRunsOutKeepsTheBoxSound) {
  std::mt19937_64 rng(17);
  const PartBox box = randomBox(rng, 0.1);
  PartExtentOptions few;
  few.budget = 10;
  Vec3 lo, hi, tightLo, tightHi;
  partExtent(box, &lo, &hi, few);
  partExtent(box, &tightLo, &tightHi);
  expectHolds(lo, hi, tightLo, tightHi);
  for (int s = 0; s < 16; ++s) {
    Vec3 a, b;
    surfaceBox(sampledPart(rng, box, s), 16, &a, &b);
    expectHolds(lo, hi, a, b);
  }
}

}  // namespace
}  // namespace fsdb
