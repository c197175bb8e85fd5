#include "geometry/fuzzy/defuzzify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/core/error.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

using testing::uniform;

TEST(Defuzzify, TriangleCentroids) {
  EXPECT_DOUBLE_EQ(centroid(FuzzyNumber::triangular(1, 3, 5)), 3);
  std::mt19937 rng(31);
  for (int i = 0; i < 200; ++i) {
    const double l = uniform(rng, -10, 10), m = l + uniform(rng, 0, 5), r = m + uniform(rng, 0, 5);
    if (r == l) continue;
    EXPECT_NEAR(centroid(FuzzyNumber::triangular(l, m, r)), (l + m + r) / 3, 1e-12);
  }
}

TEST(Defuzzify, TrapezoidCentroidMatchesNumericalIntegral) {
  const FuzzyNumber a = FuzzyNumber::trapezoidal(0, 1, 3, 7);
  double mass = 0, moment = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double x = 7.0 * (i + 0.5) / n;
    mass += a.membership(x);
    moment += x * a.membership(x);
  }
  EXPECT_NEAR(centroid(a), moment / mass, 1e-8);
  // Far from the origin the result keeps its precision.
  EXPECT_NEAR(centroid(FuzzyNumber::triangular(1e9, 1e9 + 1, 1e9 + 2)), 1e9 + 1, 1e-6);
}

TEST(Defuzzify, BisectorSplitsTheAreaInHalves) {
  std::mt19937 rng(32);
  for (int i = 0; i < 300; ++i) {
    const FuzzyNumber a = i % 2 ? testing::randomConvexPoints(rng) : testing::randomPoints(rng);
    if (a.cardinality() == 0) continue;
    const double b = bisector(a);
    // Area left of b: mu clipped by a box that ends at b.
    const double lo = a.support().lo - 1;
    const FuzzyNumber left = FuzzyNumber::trapezoidal(lo, lo, b, b);
    const double leftArea = area(pointwiseMin(a.breakpoints(), left.breakpoints()));
    EXPECT_NEAR(leftArea, a.cardinality() / 2, 1e-9);
  }
  EXPECT_DOUBLE_EQ(bisector(FuzzyNumber::triangular(0, 1, 2)), 1);
  // Right triangle rising on [0, 2]: area left of x is x^2 / 4, half of 1 at x = sqrt(2).
  EXPECT_DOUBLE_EQ(bisector(FuzzyNumber::triangular(0, 2, 2)), std::sqrt(2.0));
}

TEST(Defuzzify, BisectorInAZeroGapIsItsMiddle) {
  const FuzzyNumber twoHumps =
      FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 0}, {4, 0}, {5, 1}, {6, 0}});
  EXPECT_DOUBLE_EQ(bisector(twoHumps), 3);
}

TEST(Defuzzify, MaximaOfATrapezoid) {
  const FuzzyNumber a = FuzzyNumber::trapezoidal(0, 1, 3, 7);
  EXPECT_EQ(smallestOfMaxima(a), 1);
  EXPECT_EQ(meanOfMaxima(a), 2);
  EXPECT_EQ(largestOfMaxima(a), 3);
  const FuzzyNumber t = FuzzyNumber::triangular(0, 1, 7);
  EXPECT_EQ(smallestOfMaxima(t), 1);
  EXPECT_EQ(meanOfMaxima(t), 1);
  EXPECT_EQ(largestOfMaxima(t), 1);
}

TEST(Defuzzify, MaximaOfANonConvexCore) {
  // Core pieces [1, 2] and [4, 7]: the mean weights them by length.
  const FuzzyNumber a =
      FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 1}, {3, 0.5}, {4, 1}, {7, 1}, {8, 0}});
  EXPECT_EQ(smallestOfMaxima(a), 1);
  EXPECT_EQ(largestOfMaxima(a), 7);
  EXPECT_DOUBLE_EQ(meanOfMaxima(a), (1.5 * 1 + 5.5 * 3) / 4);
  // Two single peaks: their plain mean.
  const FuzzyNumber peaks = FuzzyNumber::fromPoints({{0, 0}, {1, 1}, {2, 0.5}, {3, 1}, {4, 0}});
  EXPECT_EQ(meanOfMaxima(peaks), 2);
}

TEST(Defuzzify, CrispAndSpikesGiveTheirValue) {
  const FuzzyNumber c = FuzzyNumber::crisp(2.5);
  for (double v : {centroid(c), bisector(c), smallestOfMaxima(c), meanOfMaxima(c),
                   largestOfMaxima(c)}) {
    EXPECT_EQ(v, 2.5);
  }
  const FuzzyNumber spikes = FuzzyNumber::fromPoints({{0, 1}, {0, 0}, {1, 0}, {1, 1}});
  EXPECT_EQ(spikes.cardinality(), 0);
  EXPECT_EQ(centroid(spikes), 0.5);
  EXPECT_EQ(bisector(spikes), 0.5);
}

TEST(Defuzzify, SymmetricNumbersDefuzzifyToTheirCentre) {
  std::mt19937 rng(33);
  for (int i = 0; i < 100; ++i) {
    const double m = uniform(rng, -5, 5), s = uniform(rng, 0.1, 3), t = uniform(rng, 0, 1);
    const FuzzyNumber a = FuzzyNumber::trapezoidal(m - s - t, m - t, m + t, m + s + t);
    EXPECT_NEAR(centroid(a), m, 1e-12);
    EXPECT_NEAR(bisector(a), m, 1e-12);
    EXPECT_NEAR(meanOfMaxima(a), m, 1e-12);
  }
}

// --- localMaxima (Bernardes, Wu & D'Ottaviano, §5, §7) -------------------------------------

TEST(LocalMaxima, HandMadeMultiPeakFunction) {
  const std::vector<Breakpoint> f = {{0, 0},   {1, 0.6}, {2, 0.2}, {3, 1},
                                     {4, 1},   {5, 0.3}, {6, 0.8}, {7, 0}};
  const auto m = localMaxima(f);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].x, 3.5);  // plateau reported once, at its midpoint
  EXPECT_EQ(m[0].mu, 1);
  EXPECT_EQ(m[1].x, 6);
  EXPECT_EQ(m[1].mu, 0.8);
  EXPECT_EQ(m[2].x, 1);
  EXPECT_EQ(m[2].mu, 0.6);
}

TEST(LocalMaxima, ThresholdRAlphaDropsLowMaxima) {
  const std::vector<Breakpoint> f = {{0, 0}, {1, 0.6}, {2, 0.2}, {3, 1}, {4, 0.3}, {6, 0.8}, {7, 0}};
  EXPECT_EQ(localMaxima(f, 0.7).size(), 2u);
  EXPECT_EQ(localMaxima(f, 0.8).size(), 2u);  // mu == threshold stays
  EXPECT_EQ(localMaxima(f, 0.81).size(), 1u);
  EXPECT_EQ(localMaxima(f, 1.5).size(), 0u);
  try {
    localMaxima(f, std::nan(""));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "threshold");
  }
}

TEST(LocalMaxima, EndsJumpsAndTies) {
  // Falling away from both ends: boundary maxima.
  auto m = localMaxima({{0, 0.9}, {1, 0.1}, {2, 0.5}});
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].x, 0);
  EXPECT_EQ(m[1].x, 2);
  // A jump's top is a maximum even with lower limits on both sides.
  m = localMaxima({{0, 0}, {1, 0.3}, {1, 0.9}, {1, 0.4}, {2, 0}});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].x, 1);
  EXPECT_EQ(m[0].mu, 0.9);
  // A dip inside a jump is not a point of the function (the value is the larger side).
  m = localMaxima({{0, 0}, {1, 0.5}, {1, 0.2}, {1, 0.5}, {2, 0}});
  ASSERT_EQ(m.size(), 1u);
  // A plateau reached by a vertical jump.
  m = localMaxima({{0, 0.2}, {2, 0.2}, {2, 0.7}, {4, 0.7}, {5, 0}});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].x, 3);
  // Equal heights: x ascending.
  m = localMaxima({{0, 0}, {5, 0.5}, {6, 0}, {7, 0.5}, {8, 0}, {9, 0.5}, {10, 0}});
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].x, 5);
  EXPECT_EQ(m[1].x, 7);
  EXPECT_EQ(m[2].x, 9);
  // Constant: one plateau. Empty: nothing.
  m = localMaxima({{0, 0.4}, {10, 0.4}});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].x, 5);
  EXPECT_TRUE(localMaxima({}).empty());
}

TEST(LocalMaxima, RoundingNoiseDoesNotSplitAPlateau) {
  const auto m = localMaxima({{0, 0}, {1, 1}, {2, 1 - 1e-16}, {3, 1}, {4, 0}});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].x, 2);
}

TEST(LocalMaxima, RejectsMalformedInput) {
  try {
    localMaxima({{0, 0}, {2, 1}, {1, 0}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "[2]");
  }
}

// Bernardes, Wu & D'Ottaviano, §5 example: F4 over radius-vector angles with maxima (4; 0.10),
// (73; 0.67), (146; 0.13), (166; 0.09). A sum of bumps sampled at 180 angles reproduces that
// ranking.
TEST(LocalMaxima, SampledSumOfBumpsOverAngles) {
  const double centres[] = {4, 73, 146, 166}, heights[] = {0.10, 0.67, 0.13, 0.09};
  std::vector<Breakpoint> f;
  for (int deg = 0; deg < 180; ++deg) {
    double mu = 0;
    for (int k = 0; k < 4; ++k) mu += heights[k] * std::exp(-std::pow((deg - centres[k]) / 3.0, 2));
    f.push_back({static_cast<double>(deg), mu});
  }
  auto m = localMaxima(f);
  ASSERT_EQ(m.size(), 4u);
  const double expectedX[] = {73, 146, 4, 166};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m[k].x, expectedX[k]);
  EXPECT_NEAR(m[0].mu, 0.67, 1e-9);
  EXPECT_NEAR(m[3].mu, 0.09, 1e-9);
  // Bernardes, Wu & D'Ottaviano, §7: R_alpha = 0.1 discards the improbable 166 degrees.
  m = localMaxima(f, 0.1);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[2].x, 4);
}

// On random samples with distinct values the maxima are exactly the samples above both
// neighbours (or above the one neighbour at an end).
TEST(LocalMaxima, RandomSamplesMatchNeighbourComparison) {
  std::mt19937 rng(34);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Breakpoint> f;
    const int n = 2 + trial % 60;
    for (int i = 0; i < n; ++i) f.push_back({i * 0.5, uniform(rng, 0, 1)});
    std::vector<double> expected;
    for (int i = 0; i < n; ++i) {
      const bool left = i == 0 || f[i - 1].mu < f[i].mu;
      const bool right = i + 1 == n || f[i + 1].mu < f[i].mu;
      if (left && right) expected.push_back(f[i].x);
    }
    const auto m = localMaxima(f);
    ASSERT_EQ(m.size(), expected.size());
    for (size_t k = 0; k < m.size(); ++k) {
      EXPECT_NE(std::find(expected.begin(), expected.end(), m[k].x), expected.end());
      EXPECT_EQ(m[k].mu, valueAt(f, m[k].x));
      if (k > 0) {
        EXPECT_GE(m[k - 1].mu, m[k].mu);
      }
    }
  }
}

}  // namespace
}  // namespace fsdb
