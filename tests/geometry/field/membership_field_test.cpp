// geometry/field/membership_field: a membership μ as an alpha field, Π = min(1, 2μ), N = max(0, 2μ − 1).
#include "geometry/field/membership_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/geometry/block_lattice.h"

namespace fsdb {
namespace {

TEST(MembershipField, LevelsOfAMembership) {
  EXPECT_EQ(levelsFromMembership(0.0).upper, 0.0f);
  EXPECT_EQ(levelsFromMembership(0.0).lower, kNeverInside);
  EXPECT_EQ(levelsFromMembership(0.25).upper, 0.5f);
  EXPECT_EQ(levelsFromMembership(0.25).lower, kNeverInside);
  // The 0.5 level is the core: u = 1 from there, N = 0 exactly there (lower(1) = {μ > 1/2}).
  EXPECT_EQ(levelsFromMembership(0.5).upper, 1.0f);
  EXPECT_EQ(levelsFromMembership(0.5).lower, kNeverInside);
  EXPECT_EQ(levelsFromMembership(std::nextafter(0.5, 0.0)).upper, std::nextafter(1.0f, 0.0f));
  EXPECT_EQ(levelsFromMembership(0.75).upper, 1.0f);
  EXPECT_EQ(levelsFromMembership(0.75).lower, 0.5f);
  EXPECT_EQ(levelsFromMembership(1.0).lower, 0.0f);
  EXPECT_EQ(levelsFromMembership(1.5).lower, 0.0f);  // clamped
  EXPECT_EQ(levelsFromMembership(-0.5).upper, 0.0f);
}

// upper(α) = {μ ≥ α/2} and lower(α) = {μ ≥ 1 − α/2} on a fine grid of μ and α: nested in α,
// lower ⊆ core = {μ ≥ 1/2} ⊆ upper (up to the float rounding of u down and l up, which only
// shrinks both sets).
TEST(MembershipField, CutsAreTheHalvedMembershipLevelsAndNest) {
  for (int i = 0; i <= 1000; ++i) {
    const double mu = i / 1000.0;
    const AlphaLevels v = levelsFromMembership(mu);
    EXPECT_EQ(v.upper == 1.0f, mu >= 0.5) << mu;  // the core
    for (int j = 0; j <= 64; ++j) {
      const double alpha = j / 64.0;
      const bool up = inUpper(v, alpha), low = inLower(v, alpha);
      EXPECT_TRUE(!low || up) << mu << " " << alpha;
      EXPECT_TRUE(!low || mu >= 0.5) << mu << " " << alpha;
      EXPECT_TRUE(mu < 0.5 || up) << mu << " " << alpha;
      // The closed forms, away from the float rounding at the cut itself.
      if (alpha > 0.0 && std::abs(mu - alpha / 2) > 1e-6) {
        EXPECT_EQ(up, mu > alpha / 2) << mu << " " << alpha;
      }
      if (std::abs(mu - (1 - alpha / 2)) > 1e-6) {
        EXPECT_EQ(low, mu > 1 - alpha / 2) << mu << " " << alpha;
      }
    }
  }
}

TEST(MembershipField, BoundsHoldEveryMembershipOfTheRange) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    double a = unit(rng), b = unit(rng);
    if (i % 7 == 0) a = 0.5;
    if (i % 11 == 0) b = 1.0;
    const MembershipRange r{std::min(a, b), std::max(a, b)};
    const AlphaLevelBounds bounds = boundsFromMembership(r);
    for (double mu : {r.lo, r.hi, r.lo + unit(rng) * (r.hi - r.lo)})
      ASSERT_TRUE(levelsWithin(levelsFromMembership(mu), bounds)) << mu;
  }
  EXPECT_TRUE(boundsFromMembership({0.0, 0.0}).uniform());
  EXPECT_EQ(boundsFromMembership({0.0, 0.0}).lowerMin, kNeverInside);
  EXPECT_TRUE(boundsFromMembership({1.0, 1.0}).uniform());
}

// A MembershipField's levelsAt and boundsOver are the maps of its membership.
class Slab : public MembershipField {
 public:
  double membership(const Vec3& p) const override { return std::clamp(0.5 - p.x, 0.0, 1.0); }
  MembershipRange membershipOver(const Vec3& lo, const Vec3& hi) const override {
    return {membership(hi), membership(lo)};
  }
  void boundingBox(Vec3* lo, Vec3* hi) const override {
    *lo = {-0.5, -1, -1};
    *hi = {0.5, 1, 1};
  }
};

TEST(MembershipField, LevelsAndBoundsOfAFieldAreTheMapsOfItsMembership) {
  const Slab slab;
  for (double x : {-0.6, -0.2, 0.0, 0.1, 0.4}) {
    const AlphaLevels v = slab.levelsAt({x, 0, 0}), w = levelsFromMembership(0.5 - x);
    EXPECT_EQ(v.upper, w.upper);
    EXPECT_EQ(v.lower, w.lower);
  }
  const AlphaLevelBounds b = slab.boundsOver({-0.2, 0, 0}, {0.1, 0, 0});
  EXPECT_EQ(b.upperMin, levelsFromMembership(0.4).upper);
  EXPECT_EQ(b.upperMax, 1.0f);
  EXPECT_EQ(b.lowerMin, levelsFromMembership(0.7).lower);
  EXPECT_EQ(b.lowerMax, kNeverInside);
}

}  // namespace
}  // namespace fsdb
