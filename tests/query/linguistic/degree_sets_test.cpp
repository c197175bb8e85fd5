// Fuzzy sets over a descriptor's degree (query/linguistic/degree_sets.h): restriction to [0, 1]
// cuts pieces at the ends exactly, and mirroring is d → 1 − d, its own inverse up to rounding.
#include "query/linguistic/degree_sets.h"

#include <gtest/gtest.h>

#include "geometry/fuzzy/fuzzy_arithmetic.h"

namespace fsdb {
namespace {

TEST(DegreeSets, RestrictionCutsAtZeroAndOne) {
  // about 1: tri(0.9, 1, 1.1) keeps [0.9, 1] and a vertical side at 1.
  const FuzzyNumber r = restrictedToDegrees(FuzzyNumber::triangular(0.9, 1.0, 1.1));
  ASSERT_FALSE(r.breakpoints().empty());
  EXPECT_DOUBLE_EQ(r.breakpoints().front().x, 0.9);
  EXPECT_DOUBLE_EQ(r.breakpoints().back().x, 1.0);
  EXPECT_DOUBLE_EQ(r.membership(0.95), FuzzyNumber::triangular(0.9, 1.0, 1.1).membership(0.95));
  EXPECT_DOUBLE_EQ(r.membership(1.0), 1.0);
  // A piece crossing 0: the membership at 0 is the interpolated one.
  const FuzzyNumber low = restrictedToDegrees(FuzzyNumber::triangular(-0.2, 0.2, 0.6));
  EXPECT_DOUBLE_EQ(low.breakpoints().front().x, 0.0);
  EXPECT_NEAR(low.membership(0.0), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(low.membership(0.2), 1.0);
  // A set inside [0, 1] is unchanged.
  const FuzzyNumber inside = FuzzyNumber::trapezoidal(0.1, 0.2, 0.3, 0.4);
  EXPECT_EQ(restrictedToDegrees(inside), inside);
}

TEST(DegreeSets, RestrictionToANarrowerRangeCutsAtItsEnds) {
  // extremely: trap(0.8, 0.95, 1, 1) within [0.01, 0.99] keeps its rise and ends with a vertical
  // side at 0.99; what is cut away is the core beyond it.
  const FuzzyNumber extremely = FuzzyNumber::trapezoidal(0.8, 0.95, 1.0, 1.0);
  const FuzzyNumber r = restrictedToDegrees(extremely, 0.01, 0.99);
  EXPECT_DOUBLE_EQ(r.breakpoints().front().x, 0.8);
  EXPECT_DOUBLE_EQ(r.breakpoints().back().x, 0.99);
  EXPECT_DOUBLE_EQ(r.membership(0.99), 1.0);
  EXPECT_DOUBLE_EQ(r.membership(0.9), extremely.membership(0.9));
  // A sloping piece crossing an end is cut at its interpolated membership, not squeezed.
  const FuzzyNumber slope = restrictedToDegrees(FuzzyNumber::trapezoidal(0.6, 0.75, 0.9, 1.0), 0.01, 0.95);
  EXPECT_DOUBLE_EQ(slope.breakpoints().back().x, 0.95);
  EXPECT_NEAR(slope.membership(0.95), 0.5, 1e-12);
  EXPECT_NEAR(slope.membership(0.925), 0.75, 1e-12);
  // The low end the same way.
  const FuzzyNumber low = restrictedToDegrees(FuzzyNumber::trapezoidal(0.0, 0.0, 0.05, 0.2), 0.01, 0.99);
  EXPECT_DOUBLE_EQ(low.breakpoints().front().x, 0.01);
  EXPECT_DOUBLE_EQ(low.membership(0.01), 1.0);
}

// withinDegrees: a set is cut at an end of a descriptor's domain inside the scale where it
// reaches beyond it and its core reaches inside; otherwise it is kept.
TEST(DegreeSets, WithinDegreesCutsAtTheDomainsInnerEnds) {
  const FuzzyNumber very = FuzzyNumber::trapezoidal(0.55, 0.75, 1.0, 1.0);
  const FuzzyNumber cut = withinDegrees(very, 0.0, 0.99);
  EXPECT_EQ(cut, restrictedToDegrees(very, 0.55, 0.99));
  EXPECT_DOUBLE_EQ(cut.support().hi, 0.99);
  EXPECT_DOUBLE_EQ(cut.membership(0.99), 1.0);
  EXPECT_DOUBLE_EQ(cut.core().lo, 0.75);
  // At the low end: slightly = trap(0, 0.1, 0.25, 0.4) starts at 0.01 with its membership there.
  const FuzzyNumber slightly = FuzzyNumber::trapezoidal(0.0, 0.1, 0.25, 0.4);
  const FuzzyNumber low = withinDegrees(slightly, 0.01, 0.99);
  EXPECT_DOUBLE_EQ(low.support().lo, 0.01);
  EXPECT_NEAR(low.membership(0.01), 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(low.support().hi, 0.4);
  // The whole scale cuts nothing, and a set within the domain is unchanged.
  EXPECT_EQ(withinDegrees(very, 0.0, 1.0), very);
  EXPECT_EQ(withinDegrees(slightly, 0.0, 1.0), slightly);
  EXPECT_EQ(withinDegrees(FuzzyNumber::trapezoidal(0.2, 0.3, 0.4, 0.5), 0.01, 0.99),
            FuzzyNumber::trapezoidal(0.2, 0.3, 0.4, 0.5));
  // An end at 0 or 1 keeps what lies beyond it (a closest-match set widened below 0).
  const FuzzyNumber widened = FuzzyNumber::trapezoidal(-0.3, 0.0, 0.2, 0.5);
  EXPECT_EQ(withinDegrees(widened, 0.0, 0.99), widened);
  // A core wholly beyond the end (the plain ramp of "square", 1 only at 1) is kept: cut, it
  // would have no core.
  const FuzzyNumber ramp = FuzzyNumber::triangular(0.0, 1.0, 1.0);
  EXPECT_EQ(withinDegrees(ramp, 0.0, 0.99), ramp);
  EXPECT_EQ(withinDegrees(FuzzyNumber::crisp(1.0), 0.0, 0.99), FuzzyNumber::crisp(1.0));
}

TEST(DegreeSets, MirroringIsOneMinusTheDegree) {
  const FuzzyNumber set = FuzzyNumber::trapezoidal(0.0, 0.1, 0.25, 0.4);
  const FuzzyNumber m = mirroredDegrees(set);
  for (double d : {0.0, 0.05, 0.1, 0.3, 0.6, 0.8, 0.95, 1.0}) EXPECT_NEAR(m.membership(d), set.membership(1.0 - d), 1e-12) << d;
  // Twice is the set again, up to the rounding of 1 − (1 − d).
  const FuzzyNumber twice = mirroredDegrees(m);
  for (double d : {0.0, 0.05, 0.1, 0.3, 0.6}) EXPECT_NEAR(twice.membership(d), set.membership(d), 1e-12) << d;
  // The same set as the affine map 1 − d written with scale (parts from words used it).
  EXPECT_EQ(m, add(scale(set, -1.0), FuzzyNumber::crisp(1.0)));
}

}  // namespace
}  // namespace fsdb
