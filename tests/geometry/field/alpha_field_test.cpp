// geometry/field/alpha_field.h: the per-point Booleans on (u, l) and level membership (docs/api.md
// §3). Laws on random levels, the background as identity or absorber, and the defining property:
// membership of a Boolean at α equals the Boolean of the memberships (for difference, away
// from the single level α = l_B or α = u_B that the header excepts).
#include "geometry/field/alpha_field.h"

#include <gtest/gtest.h>

#include <random>

namespace fsdb {
namespace {

// Levels of a point of a solid that satisfies lower ⊆ upper: l ≤ 1 forces u = 1.
AlphaLevels randomLevels(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 3);
  std::uniform_int_distribution<int> step(0, 8);  // multiples of 1/8: ties between a and b
  const float x = step(rng) / 8.0f;
  switch (kind(rng)) {
    case 0: return AlphaLevels{};              // background
    case 1: return {x, kNeverInside};         // possibly inside only
    case 2: return {1.0f, x};                 // necessarily inside from level x on
    default: return {x, kNeverInside};
  }
}

bool same(AlphaLevels a, AlphaLevels b) { return a.upper == b.upper && a.lower == b.lower; }

TEST(AlphaField, UnionAndIntersectionAreCommutativeAndAssociative) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 2000; ++i) {
    const AlphaLevels a = randomLevels(rng), b = randomLevels(rng), c = randomLevels(rng);
    EXPECT_TRUE(same(alphaUnion(a, b), alphaUnion(b, a)));
    EXPECT_TRUE(same(alphaIntersection(a, b), alphaIntersection(b, a)));
    EXPECT_TRUE(same(alphaUnion(alphaUnion(a, b), c), alphaUnion(a, alphaUnion(b, c))));
    EXPECT_TRUE(same(alphaIntersection(alphaIntersection(a, b), c),
                     alphaIntersection(a, alphaIntersection(b, c))));
    EXPECT_TRUE(same(alphaUnion(a, a), a));
    EXPECT_TRUE(same(alphaIntersection(a, a), a));
  }
}

TEST(AlphaField, BackgroundIsIdentityOrAbsorber) {
  std::mt19937_64 rng(4);
  const AlphaLevels bg{};
  EXPECT_EQ(bg.upper, 0.0f);
  EXPECT_EQ(bg.lower, kNeverInside);
  for (int i = 0; i < 500; ++i) {
    const AlphaLevels a = randomLevels(rng);
    EXPECT_TRUE(same(alphaUnion(a, bg), a));
    EXPECT_TRUE(same(alphaIntersection(a, bg), bg));
    // a − background: u = min(uA, never) = uA, l = max(lA, 0) = lA.
    EXPECT_TRUE(same(alphaDifference(a, bg), a));
    EXPECT_TRUE(same(alphaDifference(bg, a), bg));
  }
}

TEST(AlphaField, MembershipAtOneLevel) {
  EXPECT_FALSE(inUpper(AlphaLevels{}, 0.0));  // u = 0: not even in upper(0)'s interior
  EXPECT_FALSE(inLower(AlphaLevels{}, 1.0));
  const AlphaLevels shell{0.5f, kNeverInside};
  EXPECT_TRUE(inUpper(shell, 0.0));
  EXPECT_TRUE(inUpper(shell, 0.5));
  EXPECT_FALSE(inUpper(shell, 0.51));
  EXPECT_FALSE(inLower(shell, 1.0));
  const AlphaLevels core{1.0f, 0.375f};
  EXPECT_TRUE(inUpper(core, 1.0));
  EXPECT_TRUE(inLower(core, 0.375));
  EXPECT_FALSE(inLower(core, 0.37));
  // Levels are floats and α a double: 0.3f > 0.3, so a point with l = 0.3f is not in lower(0.3).
  EXPECT_FALSE(inLower(AlphaLevels{1.0f, 0.3f}, 0.3));
}

TEST(AlphaField, BooleanOfMembershipsAtEveryLevel) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> level(0.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const AlphaLevels a = randomLevels(rng), b = randomLevels(rng);
    const double alpha = level(rng);  // continuous: never one of the levels (multiples of 1/8)
    const AlphaLevels u = alphaUnion(a, b), n = alphaIntersection(a, b), d = alphaDifference(a, b);
    EXPECT_EQ(inUpper(u, alpha), inUpper(a, alpha) || inUpper(b, alpha));
    EXPECT_EQ(inLower(u, alpha), inLower(a, alpha) || inLower(b, alpha));
    EXPECT_EQ(inUpper(n, alpha), inUpper(a, alpha) && inUpper(b, alpha));
    EXPECT_EQ(inLower(n, alpha), inLower(a, alpha) && inLower(b, alpha));
    // docs/api.md §3: A − B = (lower_A − upper_B, upper_A − lower_B).
    EXPECT_EQ(inLower(d, alpha), inLower(a, alpha) && !inUpper(b, alpha));
    EXPECT_EQ(inUpper(d, alpha), inUpper(a, alpha) && !inLower(b, alpha));
    // Nesting survives: lower ⊆ upper.
    for (const AlphaLevels& r : {u, n, d})
      EXPECT_TRUE(!inLower(r, alpha) || inUpper(r, alpha));
  }
}

// The end levels, where whole regions share a level (cores: u = 1, l = 0; outside: u = 0).
// A point in B's core (uB = 1) is in upper_B(1), so it is in no lower(α) of A − B.
TEST(AlphaField, DifferenceAtTheEndLevels) {
  std::mt19937_64 rng(6);
  for (int i = 0; i < 5000; ++i) {
    const AlphaLevels a = randomLevels(rng), b = randomLevels(rng);
    const AlphaLevels d = alphaDifference(a, b);
    for (double alpha : {0.0, 1.0}) {
      EXPECT_EQ(inLower(d, alpha), inLower(a, alpha) && !inUpper(b, alpha)) << alpha;
      if (b.lower != 1.0f) {  // the measure-zero boundary lB = 1 (header)
        EXPECT_EQ(inUpper(d, alpha), inUpper(a, alpha) && !inLower(b, alpha)) << alpha;
      }
    }
  }
  EXPECT_EQ(alphaDifference({1.0f, 0.0f}, {1.0f, 0.5f}).lower, kNeverInside);
}

}  // namespace
}  // namespace fsdb
