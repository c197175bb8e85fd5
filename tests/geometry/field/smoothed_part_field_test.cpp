// geometry/field/smoothed_part_field: a crisp part as μ(F(P)) = step(−d/R) (Li & Tian, §2.1).
#include "geometry/field/smoothed_part_field.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/geometry/block_lattice.h"
#include "tests/geometry/expect_error.h"
#include "geometry/field/node_operator.h"
#include "geometry/operators/step_functions.h"

namespace fsdb {
namespace {

// A crisp sphere of radius r at c (scale r on the unit sphere).
std::shared_ptr<const FuzzyPartField> sphere(Vec3 c, double r) {
  PlacedSuperquadric s;
  s.placement.translate = c;
  s.placement.scale = r;
  return std::make_shared<const FuzzyPartField>(FuzzyPart::fromCrisp(s));
}

TEST(SmoothedPartField, MembershipIsTheStepOfMinusDistanceOverRange) {
  const auto leaf = sphere({1, 2, 3}, 2.0);
  const SmoothedPartField f(leaf, {0.5, {"polynomial", {{"n", 3.0}}, {}}});
  EXPECT_EQ(f.range(), 0.5);
  for (double d : {-0.7, -0.5, -0.2, 0.0, 0.1, 0.3, 0.49, 0.6}) {
    const Vec3 p{1 + 2.0 + d, 2, 3};  // the pseudo distance of a sphere is the distance
    EXPECT_NEAR(f.membership(p), polynomialStep(3, -d / 0.5), 1e-12) << d;
  }
  EXPECT_NEAR(f.membership({3, 2, 3}), 0.5, 1e-12);  // the surface is the 0.5 level
  // Levels: Π = min(1, 2μ), N = max(0, 2μ − 1) (membership_field.h).
  const AlphaLevels outside = f.levelsAt({3.1, 2, 3});
  EXPECT_NEAR(outside.upper, 2 * polynomialStep(3, -0.2), 1e-6);
  EXPECT_EQ(outside.lower, kNeverInside);
  const AlphaLevels inside = f.levelsAt({2.9, 2, 3});
  EXPECT_EQ(inside.upper, 1.0f);
  EXPECT_NEAR(necessityOf(inside), 2 * polynomialStep(3, 0.2) - 1, 1e-6);
  EXPECT_EQ(f.levelsAt({3, 2, 3}).upper, 1.0f);  // the surface is in the core
  EXPECT_EQ(f.levelsAt({0, 0, 10}).lower, kNeverInside);
  EXPECT_EQ(f.levelsAt({1, 2, 3}).lower, 0.0f);  // deep inside: μ = 1
}

TEST(SmoothedPartField, DefaultRangeIsATenthOfTheSmallestHalfLengthTimesScale) {
  PlacedSuperquadric s;
  s.params.a1 = 2.0;
  s.params.a2 = 0.5;  // B = 1
  s.params.a3 = 3.0;
  s.placement.scale = 4.0;
  EXPECT_DOUBLE_EQ(defaultSmoothingRange(s), 0.1 * 4.0 * 1.0);
  const auto leaf = std::make_shared<const FuzzyPartField>(FuzzyPart::fromCrisp(s));
  EXPECT_DOUBLE_EQ(SmoothedPartField(leaf, {}).range(), 0.4);
}

TEST(SmoothedPartField, ZeroOutsideTheGrownBoxAndTheBoxCutIsInactiveForUndeformedParts) {
  const auto leaf = sphere({0, 0, 0}, 1.0);
  const SmoothedPartField f(leaf, {0.3, {"polynomial", {{"n", 3.0}}, {}}});
  Vec3 lo, hi, plo, phi;
  f.boundingBox(&lo, &hi);
  leaf->boundingBox(&plo, &phi);
  EXPECT_DOUBLE_EQ(hi.x, phi.x + 0.3);
  EXPECT_DOUBLE_EQ(lo.z, plo.z - 0.3);
  // Just inside the grown box: at distance R from the sphere the step has (all but) reached 0,
  // and farther than R (a corner) it is 0 exactly.
  EXPECT_LT(f.membership({hi.x - 1e-9, 0, 0}), 1e-20);
  EXPECT_EQ(f.membership({hi.x - 1e-9, hi.y - 1e-9, 0}), 0.0);
  EXPECT_EQ(f.membership({hi.x + 1e-9, 0, 0}), 0.0);
  EXPECT_GT(f.membership({1.29, 0, 0}), 0.0);
}

TEST(SmoothedPartField, BoundsHoldTheLevelsOfEveryPointOfTheBox) {
  const auto leaf = sphere({0.2, 0, 0}, 1.0);
  const SmoothedPartField f(leaf, {0.25, {"bspline", {{"m", 3.0}}, {}}});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> c(-2.0, 2.0), w(0.0, 0.6), t(0.0, 1.0);
  int exact = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 lo{c(rng), c(rng), c(rng)}, hi = lo + Vec3{w(rng), w(rng), w(rng)};
    const AlphaLevelBounds b = f.boundsOver(lo, hi);
    const MembershipRange m = f.membershipOver(lo, hi);
    exact += b.uniform();
    for (int k = 0; k < 10; ++k) {
      const Vec3 p{lo.x + t(rng) * (hi.x - lo.x), lo.y + t(rng) * (hi.y - lo.y), lo.z + t(rng) * (hi.z - lo.z)};
      const AlphaLevels v = f.levelsAt(p);
      ASSERT_TRUE(levelsWithin(v, b));
      ASSERT_GE(f.membership(p), m.lo);
      ASSERT_LE(f.membership(p), m.hi);
    }
  }
  EXPECT_GT(exact, 100);  // boxes outside the grown box are proven empty
}

TEST(SmoothedPartField, RefusesBadRangesStepsAndFuzzyParts) {
  const auto leaf = sphere({0, 0, 0}, 1.0);
  expectInvalidParameter([&] { SmoothedPartField(leaf, {0.0, {"polynomial", {}, {}}}); }, "range");
  expectInvalidParameter([&] { SmoothedPartField(leaf, {-1.0, {"polynomial", {}, {}}}); }, "range");
  expectInvalidParameter([&] { SmoothedPartField(leaf, {{}, {"polynomial", {{"n", 40.0}}, {}}}); }, "step.n");
  expectInvalidParameter([&] { SmoothedPartField(leaf, {{}, {"polynomial", {{"epsilon", 2.0}}, {}}}); },
                         "step.epsilon");
  expectInvalidParameter([&] { SmoothedPartField(leaf, {{}, {"yager", {}, {}}}); }, "step.name");
  // R_n(0) = sin(π/4): the part's surface would not be the 0.5 level.
  expectInvalidParameter([&] { SmoothedPartField(leaf, {{}, {"rising_cutoff", {}, {}}}); }, "step.name");
  EXPECT_NO_THROW(validateLeafSmoothing({{}, {"rising_cutoff_squared", {}, {}}}));
  FuzzyPart fuzzy;
  fuzzy.a1 = FuzzyNumber::triangular(0.9, 1.0, 1.1);
  const auto fuzzyLeaf = std::make_shared<const FuzzyPartField>(fuzzy);
  try {
    SmoothedPartField(fuzzyLeaf, {});
    ADD_FAILURE() << "a fuzzy part was smoothed";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
  }
}

}  // namespace
}  // namespace fsdb
