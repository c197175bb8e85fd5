// Ranked candidate fair curves (Bernardes, Wu & D'Ottaviano, §5-§7;
// geometry/curves/fair_candidates.h).
#include "geometry/curves/fair_candidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "geometry/curves/fair_curve.h"
#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

// Bernardes, Wu & D'Ottaviano, Figure 7: "a first estimation of an interpolatory closed curve" from
// four points. The text gives no coordinates; this convex quadrilateral (found by a search over
// small integer quadrilaterals for the one whose F_4 at P1 comes closest to the paper's maxima)
// stands in for it.
const std::vector<Vec2> kFigure7 = {{0, 0}, {-5, -1}, {-3, -4}, {1, -1}};

TEST(FairCandidates, Figure7P1HasTheFourMaximaOfThePaper) {
  const auto angles = firstEstimationAngles(kFigure7, true);
  const auto m = fairAngleMaxima(fairDangerZones(kFigure7, angles, true, 0, FairBehavior::kUndulant), 180, 0);
  // Bernardes, Wu & D'Ottaviano, §5: M1 = (4; 0.10), M2 = (73; 0.67), M3 = (146; 0.13), M4 =
  // (166; 0.09).
  const double paperX[] = {73, 146, 166, 4}, paperMu[] = {0.67, 0.13, 0.09, 0.10};
  ASSERT_EQ(m.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(directionDistance(m[k].x, paperX[k]), 0, 1.0) << k << ": " << m[k].x;
    EXPECT_NEAR(m[k].mu, paperMu[k], 0.02) << k << ": " << m[k].mu;
  }
  // F_4 is the min of four Figure 3 ramps, so its maxima's grades sum to 1 (the paper's: 0.99).
  double sum = 0;
  for (const auto& r : m) sum += r.mu;
  EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(FairCandidates, Figure7YieldsSeveralDistinctRankedCandidates) {
  FairCandidateOptions o;
  o.behavior = FairBehavior::kUndulant;
  o.maxCandidates = 100;
  const auto c = fairCandidates(kFigure7, true, o);
  ASSERT_GE(c.size(), 8u);
  std::set<std::vector<double>> distinct;
  for (size_t k = 0; k < c.size(); ++k) {
    distinct.insert(c[k].anglesDeg);
    if (k > 0) {
      EXPECT_GE(c[k - 1].score, c[k].score) << k;
    }
    EXPECT_LE(c[k].score, c[k].membership + 1e-12) << k;  // the AND includes the point's own grade
    const auto grades = pointFairness(kFigure7, c[k].anglesDeg, true, o.behavior);
    EXPECT_NEAR(c[k].score, *std::min_element(grades.begin(), grades.end()), 1e-12) << k;
    EXPECT_NEAR(grades[c[k].point], c[k].membership, 1e-7) << k;
  }
  EXPECT_EQ(distinct.size(), c.size());
  // Distinct beyond rounding, too: every pair differs by more than 1e-6° at some point.
  for (size_t a = 0; a < c.size(); ++a)
    for (size_t b = a + 1; b < c.size(); ++b) {
      double most = 0;
      for (size_t k = 0; k < 4; ++k) most = std::max(most, directionDistance(c[a].anglesDeg[k], c[b].anglesDeg[k]));
      EXPECT_GT(most, 1e-6) << a << " " << b;
    }
  // Every candidate curve interpolates the points.
  const auto r = radiusMagnitudes(kFigure7, {}, true);
  for (const auto& cand : c) {
    const FairCurve curve = buildFairCurve(kFigure7, cand.anglesDeg, r, true);
    for (size_t k = 0; k < 4; ++k) EXPECT_LT(length(fairCurvePoint(curve, k, 0) - kFigure7[k]), 1e-9);
  }
}

TEST(FairCandidates, ThresholdAndLimitCutTheList) {
  FairCandidateOptions o;
  o.behavior = FairBehavior::kUndulant;
  o.maxCandidates = 100;
  const auto all = fairCandidates(kFigure7, true, o);
  o.alphaThreshold = 0.3;
  const auto high = fairCandidates(kFigure7, true, o);
  EXPECT_LT(high.size(), all.size());
  for (const auto& c : high) EXPECT_GE(c.membership, 0.3);
  size_t expected = 0;
  for (const auto& c : all) expected += c.membership >= 0.3;
  EXPECT_EQ(high.size(), expected);
  o.alphaThreshold = 0;
  o.maxCandidates = 3;
  const auto three = fairCandidates(kFigure7, true, o);
  ASSERT_EQ(three.size(), 3u);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(three[k].anglesDeg, all[k].anglesDeg);
  o.maxCandidates = 0;
  expectInvalidParameter([&] { fairCandidates(kFigure7, true, o); }, "max_candidates");
}

TEST(FairCandidates, BehavioursChangeTheSets) {
  const std::vector<Vec2> zigzag = {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}};
  FairCandidateOptions o;
  o.maxCandidates = 1000;
  for (FairBehavior b : {FairBehavior::kUndulant, FairBehavior::kNoInflection, FairBehavior::kInflection}) {
    o.behavior = b;
    const auto c = fairCandidates(zigzag, false, o);
    EXPECT_FALSE(c.empty());
    for (const auto& cand : c) EXPECT_GT(cand.membership, 0);
  }
}

// Every candidate curve (not only the first estimation) passes through the points and keeps its
// tangent's direction across every point: random closed loops and open zigzags, all behaviours.
TEST(FairCandidates, EveryCandidateCurveIsG1AtEveryPoint) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int joints = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 4 + trial % 8;
    const bool closed = trial % 2;
    std::vector<Vec2> p;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n, r = 3 + u(rng);
      p.push_back(closed ? Vec2{r * std::cos(a), r * std::sin(a)} : Vec2{double(i), 2 * u(rng)});
    }
    FairCandidateOptions o;
    o.maxCandidates = 100;
    o.behavior = static_cast<FairBehavior>(trial % 3);
    const auto r = radiusMagnitudes(p, {}, closed);
    for (const auto& c : fairCandidates(p, closed, o)) {
      const FairCurve curve = buildFairCurve(p, c.anglesDeg, r, closed);
      const size_t pieces = pieceCount(curve);
      for (size_t k = 0; k < pieces; ++k)
        ASSERT_LT(length(fairCurvePoint(curve, k, 0) - p[k]), 1e-9) << trial;
      for (size_t k = 0; k + 1 < pieces || (closed && k < pieces); ++k, ++joints)
        ASSERT_GT(dot(fairCurveDerivative(curve, k, 1), fairCurveDerivative(curve, (k + 1) % pieces, 0)), 0)
            << "trial " << trial << " point " << (k + 1) % n;
    }
  }
  EXPECT_GT(joints, 1000);
}

}  // namespace
}  // namespace fsdb
