#include "geometry/fuzzy/fuzzy_similarity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using testing::uniform;

FuzzyNumber randomAny(std::mt19937& rng, int i) {
  switch (i % 4) {
    case 0: return testing::randomTriOrTrap(rng);
    case 1: return testing::randomConvexPoints(rng);
    case 2: return testing::randomPoints(rng);
    default: return FuzzyNumber::crisp(uniform(rng, -8, 8));
  }
}

// Midpoint-rule integral of min(mu_A, mu_B).
double bruteIntersection(const FuzzyNumber& a, const FuzzyNumber& b) {
  const double lo = std::min(a.support().lo, b.support().lo);
  const double hi = std::max(a.support().hi, b.support().hi);
  const int n = 200000;
  const double h = (hi - lo) / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = lo + (i + 0.5) * h;
    sum += h * std::min(a.membership(x), b.membership(x));
  }
  return sum;
}

TEST(FuzzySimilarity, HandComputedTriangles) {
  // Overlap of tri(0,1,2) and tri(1,2,3): a triangle on [1, 2] of height 1/2, area 1/4.
  const FuzzyNumber a = FuzzyNumber::triangular(0, 1, 2), b = FuzzyNumber::triangular(1, 2, 3);
  EXPECT_DOUBLE_EQ(cardinalityOfIntersection(a, b), 0.25);
  EXPECT_DOUBLE_EQ(similarity(a, b), 0.25);  // min(0.25 / 1, 0.25 / 1)
  // tri(1,2,3) lies under tri(0,2,4): the intersection is the small one, area 1; |A| = 2.
  const FuzzyNumber wide = FuzzyNumber::triangular(0, 2, 4), narrow = FuzzyNumber::triangular(1, 2, 3);
  EXPECT_DOUBLE_EQ(cardinalityOfIntersection(wide, narrow), 1.0);
  EXPECT_DOUBLE_EQ(similarity(wide, narrow), 0.5);  // min(1 / 2, 1 / 1)
}

TEST(FuzzySimilarity, CrispValueAgainstAConditionIsItsMembership) {
  // Zhang, Pham & Chen, §5: "the similarity measure degenerates to the membership degree".
  const FuzzyNumber condition = FuzzyNumber::trapezoidal(0, 1, 2, 4);
  for (double x : {-1.0, 0.5, 1.5, 3.0, 3.5, 4.0}) {
    EXPECT_DOUBLE_EQ(similarity(FuzzyNumber::crisp(x), condition), condition.membership(x));
    EXPECT_DOUBLE_EQ(similarity(condition, FuzzyNumber::crisp(x)), condition.membership(x));
  }
  EXPECT_EQ(similarity(FuzzyNumber::crisp(2), FuzzyNumber::crisp(2)), 1);
  EXPECT_EQ(similarity(FuzzyNumber::crisp(2), FuzzyNumber::crisp(2.5)), 0);
  // A jump counts with its upper side.
  EXPECT_EQ(similarity(FuzzyNumber::crisp(1), FuzzyNumber::trapezoidal(1, 1, 2, 2)), 1);
}

TEST(FuzzySimilarity, CoverageIsTheShareOfTheConditionTheValueSpans) {
  // The second ratio of S: |A ∩ B| / |B|.
  const FuzzyNumber wide = FuzzyNumber::triangular(0, 2, 4), narrow = FuzzyNumber::triangular(1, 2, 3);
  EXPECT_DOUBLE_EQ(coverage(wide, narrow), 1.0);  // 1 / 1: the wide value spans the whole condition
  EXPECT_DOUBLE_EQ(coverage(narrow, wide), 0.5);  // 1 / 2
  EXPECT_DOUBLE_EQ(coverage(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(1, 2, 3)), 0.25);
  EXPECT_EQ(coverage(narrow, narrow), 1);
  // A crisp value spans nothing of a condition with area, even at its core, where S is 1.
  EXPECT_EQ(similarity(FuzzyNumber::crisp(2), narrow), 1);
  EXPECT_EQ(coverage(FuzzyNumber::crisp(2), narrow), 0);
  // Against a crisp condition: the height of A ∩ B, as S.
  EXPECT_DOUBLE_EQ(coverage(narrow, FuzzyNumber::crisp(1.5)), 0.5);
  EXPECT_EQ(coverage(FuzzyNumber::crisp(1.5), FuzzyNumber::crisp(1.5)), 1);
  EXPECT_EQ(coverage(FuzzyNumber::crisp(1.5), FuzzyNumber::crisp(2)), 0);
  // In [0, 1] and never below S wherever the value has area (S is the smaller of the two ratios).
  std::mt19937 rng(7);
  for (int i = 0; i < 400; ++i) {
    const FuzzyNumber a = randomAny(rng, i), b = randomAny(rng, i / 4);
    const double c = coverage(a, b);
    EXPECT_GE(c, 0);
    EXPECT_LE(c, 1);
    if (a.cardinality() > 0) {
      EXPECT_GE(c, similarity(a, b) - 1e-12) << i;
    }
  }
}

TEST(FuzzySimilarity, DisjointOrTouchingSupportsGiveZero) {
  EXPECT_EQ(similarity(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(3, 4, 5)), 0);
  EXPECT_EQ(similarity(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(2, 3, 4)), 0);
  EXPECT_EQ(cardinalityOfIntersection(FuzzyNumber::triangular(0, 1, 2),
                                      FuzzyNumber::triangular(3, 4, 5)),
            0);
}

TEST(FuzzySimilarity, HeightOfIntersection) {
  EXPECT_DOUBLE_EQ(heightOfIntersection(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(1, 2, 3)), 0.5);
  // Touching only where both are 0, or apart: no common value.
  EXPECT_EQ(heightOfIntersection(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(2, 3, 4)), 0);
  EXPECT_EQ(heightOfIntersection(FuzzyNumber::triangular(0, 1, 2), FuzzyNumber::triangular(3, 4, 5)), 0);
  // Touching where both are 1 (two trapezoids meeting at a core's end), and a crisp value.
  EXPECT_EQ(heightOfIntersection(FuzzyNumber::trapezoidal(0, 1, 2, 2), FuzzyNumber::trapezoidal(2, 2, 3, 4)), 1);
  EXPECT_DOUBLE_EQ(heightOfIntersection(FuzzyNumber::crisp(0.25), FuzzyNumber::triangular(0, 1, 2)), 0.25);
  // An overlap narrower than any grid of 1/1000 is still found.
  EXPECT_GT(heightOfIntersection(FuzzyNumber::triangular(0, 0.5, 0.5002), FuzzyNumber::triangular(0.5001, 0.6, 0.7)), 0);
  // Against a fine sampling of min(mu_A, mu_B) on random numbers of every form: never below it.
  std::mt19937 rng(41);
  for (int i = 0; i < 300; ++i) {
    const FuzzyNumber a = randomAny(rng, i), b = randomAny(rng, i / 4);
    double sampled = 0;
    for (int k = 0; k <= 20000; ++k) {
      const double x = -10 + 20.0 * k / 20000;
      sampled = std::max(sampled, std::min(a.membership(x), b.membership(x)));
    }
    EXPECT_GE(heightOfIntersection(a, b) + 1e-12, sampled) << i;
    EXPECT_LE(heightOfIntersection(a, b), 1.0) << i;
  }
}

TEST(FuzzySimilarity, RandomProperties) {
  std::mt19937 rng(21);
  for (int i = 0; i < 400; ++i) {
    const FuzzyNumber a = randomAny(rng, i), b = randomAny(rng, i / 4 + i);
    const double s = similarity(a, b);
    EXPECT_GE(s, 0);
    EXPECT_LE(s, 1);
    EXPECT_NEAR(s, similarity(b, a), 1e-12);
    EXPECT_EQ(similarity(a, a), 1);
    if (a.support().hi < b.support().lo || b.support().hi < a.support().lo) {
      EXPECT_EQ(s, 0);
    }
    const double common = cardinalityOfIntersection(a, b);
    EXPECT_LE(common, std::min(a.cardinality(), b.cardinality()) + 1e-12);
    // The midpoint rule misses up to a grid step at each vertical jump.
    EXPECT_NEAR(common, bruteIntersection(a, b), 2e-4);
  }
}

// Similarity falls as a number slides away from itself.
TEST(FuzzySimilarity, DecreasesWithDistance) {
  const FuzzyNumber a = FuzzyNumber::triangular(0, 1, 2);
  double previous = 1;
  for (double shift = 0.1; shift <= 2.0; shift += 0.1) {
    const double s = similarity(a, FuzzyNumber::triangular(shift, 1 + shift, 2 + shift));
    EXPECT_LT(s, previous);
    previous = s;
  }
}

// Expected membership ∫ mu_A·mu_B / ∫ mu_A: hand values, and where S and it part.
TEST(FuzzySimilarity, ExpectedMembershipHandComputed) {
  // A narrow value in a wide condition's core is wholly in it, where S is only |A| / |B|.
  const FuzzyNumber small = FuzzyNumber::trapezoidal(0, 0, 0.3, 0.45);
  const FuzzyNumber narrow = FuzzyNumber::triangular(0.1, 0.15, 0.2);
  EXPECT_EQ(expectedMembership(narrow, small), 1.0);
  EXPECT_NEAR(similarity(narrow, small), 0.05 / 0.375, 1e-12);
  // tri(0,1,2) against the ramp mu_B(x) = x / 2 on [0, 2]: ∫ mu_A·x/2 = 1/2 (A symmetric about 1),
  // over |A| = 1.
  const FuzzyNumber ramp = FuzzyNumber::fromPoints({{0, 0}, {2, 1}, {2, 0}});
  EXPECT_NEAR(expectedMembership(FuzzyNumber::triangular(0, 1, 2), ramp), 0.5, 1e-12);
  // A crisp value: its membership, as S.
  EXPECT_EQ(expectedMembership(FuzzyNumber::crisp(0.35), small), small.membership(0.35));
  EXPECT_EQ(expectedMembership(FuzzyNumber::crisp(0.5), small), 0.0);
  // Apart: 0.
  EXPECT_EQ(expectedMembership(FuzzyNumber::triangular(1, 2, 3), small), 0.0);
}

// In [0, 1], at most the largest mu_B over A's support, 1 where A lies in B's core, and the
// midpoint rule's integral.
TEST(FuzzySimilarity, ExpectedMembershipRandomProperties) {
  std::mt19937 rng(29);
  int inCore = 0;
  for (int i = 0; i < 400; ++i) {
    const FuzzyNumber a = randomAny(rng, i), b = randomAny(rng, i / 4 + i);
    const double e = expectedMembership(a, b);
    EXPECT_GE(e, 0);
    EXPECT_LE(e, 1);
    const Interval s = a.support();
    double most = std::max(b.membership(s.lo), b.membership(s.hi));
    for (const Breakpoint& p : b.breakpoints())
      if (p.x >= s.lo && p.x <= s.hi) most = std::max(most, p.mu);
    EXPECT_LE(e, most + 1e-12);
    if (a.isCrisp()) {
      EXPECT_EQ(e, heightOfIntersection(a, b));
      continue;
    }
    const int n = 200000;
    const double h = (s.hi - s.lo) / n;
    double product = 0;
    for (int k = 0; k < n; ++k) {
      const double x = s.lo + (k + 0.5) * h;
      product += h * a.membership(x) * b.membership(x);
    }
    EXPECT_NEAR(e, product / a.cardinality(), 2e-4);
    if (b.isCrisp() || !(b.core().lo <= s.lo && s.hi <= b.core().hi)) continue;
    EXPECT_EQ(e, 1.0);
    ++inCore;
  }
  // A narrow value inside a wide set's core: B's own core widened around a point of it.
  for (int i = 0; i < 50; ++i) {
    const FuzzyNumber b = testing::randomTrapezoidal(rng);
    const Interval core = b.core();
    const double x = uniform(rng, core.lo, core.hi), w = (core.hi - core.lo) / 8;
    const FuzzyNumber a = FuzzyNumber::triangular(std::max(core.lo, x - w), x, std::min(core.hi, x + w));
    if (a.cardinality() == 0) continue;
    EXPECT_EQ(expectedMembership(a, b), 1.0);
    ++inCore;
  }
  EXPECT_GT(inCore, 20);
}

}  // namespace
}  // namespace fsdb
