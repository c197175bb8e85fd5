// Fuzzification of radius-vector angles by danger zones and defuzzification by local maxima
// (Bernardes, Wu & D'Ottaviano, §4, §5, §7; geometry/curves/fair_fuzzification.h).
#include "geometry/curves/fair_fuzzification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/curves/fair_curve.h"
#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

TEST(FairFuzzification, Figure3DangerAngleIsZeroAtTheAngleAndRampsLinearlyToOne) {
  for (double c : {0.0, 30.0, 170.0}) {
    EXPECT_EQ(dangerAngleMembership(c, c), 0.0);
    EXPECT_NEAR(dangerAngleMembership(c + 90, c), 1.0, 1e-12);
    EXPECT_NEAR(dangerAngleMembership(c + 180, c), 0.0, 1e-12);  // a direction: period 180
    for (double d : {5.0, 22.5, 45.0, 80.0}) {
      EXPECT_NEAR(dangerAngleMembership(c + d, c), d / 90, 1e-12);
      EXPECT_NEAR(dangerAngleMembership(c - d, c), d / 90, 1e-12);
    }
  }
  // A narrower delta theta: the ramp reaches 1 earlier and stays there.
  EXPECT_NEAR(dangerAngleMembership(20, 0, 40), 0.5, 1e-12);
  EXPECT_EQ(dangerAngleMembership(60, 0, 40), 1.0);
}

TEST(FairFuzzification, Figure4DangerArcIsZeroInsideAndOneAtTheFurthestAngle) {
  const AngleArc arc{20, 60};  // [20, 80]; the furthest angle is 80 + 60 = 140
  for (double t : {20.0, 35.0, 50.0, 80.0}) EXPECT_EQ(dangerArcMembership(t, arc), 0.0) << t;
  EXPECT_NEAR(dangerArcMembership(140, arc), 1.0, 1e-12);
  EXPECT_NEAR(dangerArcMembership(110, arc), 0.5, 1e-12);  // linear from 80 to 140
  EXPECT_NEAR(dangerArcMembership(170, arc), 0.5, 1e-12);  // and back to 200 = 20
  EXPECT_NEAR(dangerArcMembership(5, arc), 0.25, 1e-12);
  // The whole circle is danger: 0 everywhere; an empty arc is Figure 3's shape.
  EXPECT_EQ(dangerArcMembership(100, AngleArc{0, 180}), 0.0);
  EXPECT_NEAR(dangerArcMembership(45, AngleArc{0, 0}), 0.5, 1e-12);
}

TEST(FairFuzzification, AndIsTheMinimumOfTheSets) {
  FairDangerZones z;
  z.colinear = {10, 100};
  z.parallel = {40};
  z.hasIntersectionCondition = true;
  z.intersection = AngleArc{120, 30};
  for (double t = 0; t < 180; t += 7.3) {
    const double expect = std::min({dangerAngleMembership(t, 10), dangerAngleMembership(t, 100),
                                    dangerAngleMembership(t, 40), dangerArcMembership(t, AngleArc{120, 30})});
    EXPECT_NEAR(fairMembership(z, t), expect, 1e-15) << t;
  }
}

TEST(FairFuzzification, DangerZonesComeFromTheNeighbours) {
  const std::vector<Vec2> p = {{0, 0}, {2, 0}, {3, 2}, {1, 3}};
  const std::vector<double> angles = {10, 50, 100, 170};
  const FairDangerZones z = fairDangerZones(p, angles, true, 1, FairBehavior::kUndulant);
  ASSERT_EQ(z.colinear.size(), 2u);
  EXPECT_NEAR(z.colinear[0], 0, 1e-12);                               // P_1 - P_0 along x
  EXPECT_NEAR(z.colinear[1], std::atan2(-2, -1) * 180 / M_PI + 180, 1e-12);  // P_1 - P_2
  EXPECT_EQ(z.parallel, (std::vector<double>{10, 100}));
  EXPECT_FALSE(z.hasIntersectionCondition);
  // An open end has one neighbour and no G3 condition.
  const FairDangerZones end = fairDangerZones(p, angles, false, 0, FairBehavior::kNoInflection);
  EXPECT_EQ(end.colinear.size(), 1u);
  EXPECT_FALSE(end.hasIntersectionCondition);
}

// G31 / G32 (Bernardes, Wu & D'Ottaviano, §4): sample the intersection sides directly and compare
// with the arc.
TEST(FairFuzzification, G31AndG32ZonesAreTheOddAndEvenCrossingAngles) {
  const std::vector<Vec2> p = {{0, 0}, {3, 1}, {6, 0}, {3, -4}};
  const std::vector<double> angles = {60, 95, 130, 0};
  const size_t i = 1;
  const FairDangerZones g31 = fairDangerZones(p, angles, true, i, FairBehavior::kNoInflection);
  const FairDangerZones g32 = fairDangerZones(p, angles, true, i, FairBehavior::kInflection);
  ASSERT_TRUE(g31.hasIntersectionCondition && g32.hasIntersectionCondition);
  auto side = [&](size_t j, double theta) {  // t of the intersection of line(P_i, theta) with line(P_j, R_j)
    const Vec2 u = unitAtDegrees(theta), v = unitAtDegrees(angles[j]);
    return cross(p[j] - p[i], v) / cross(u, v);
  };
  int checked = 0;
  for (double t = 0.5; t < 180; t += 1) {
    if (directionDistance(t, 60) < 1 || directionDistance(t, 130) < 1) continue;
    const bool odd = side(0, t) * side(2, t) < 0;
    EXPECT_EQ(dangerArcMembership(t, *g31.intersection) == 0, odd) << t;
    EXPECT_EQ(dangerArcMembership(t, *g32.intersection) == 0, !odd) << t;
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

TEST(FairFuzzification, LocalMaximaOfFourTentsAreTheGapMidpoints) {
  // F_4 with danger angles 10, 50, 100, 170: maxima at the midpoints of the gaps, grade gap / 180
  // (Figure 3's ramp with delta theta = 90), the wrap-around gap 170 -> 190 included.
  FairDangerZones z;
  z.colinear = {10, 100};
  z.parallel = {50, 170};
  const auto m = fairAngleMaxima(z, 180, 0);
  ASSERT_EQ(m.size(), 4u);
  const double xs[] = {135, 75, 30, 0}, mus[] = {70.0 / 180, 50.0 / 180, 40.0 / 180, 20.0 / 180};
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(directionDistance(m[k].x, xs[k]), 0, 1e-6) << k;
    EXPECT_NEAR(m[k].mu, mus[k], 1e-9) << k;
  }
  // Peaks between samples are refined: 36 samples (5°) still find the exact peak.
  z.colinear = {10, 101.3};
  const auto coarse = fairAngleMaxima(z, 36, 0);
  EXPECT_NEAR(coarse[0].x, 135.65, 1e-6);
  EXPECT_NEAR(coarse[0].mu, 68.7 / 180, 1e-9);
}

TEST(FairFuzzification, RAlphaThresholdDropsLowMaxima) {
  FairDangerZones z;
  z.colinear = {10, 100};
  z.parallel = {50, 170};
  EXPECT_EQ(fairAngleMaxima(z, 180, 0.25).size(), 2u);  // 0.389 and 0.278 stay
  EXPECT_EQ(fairAngleMaxima(z, 180, 0.3).size(), 1u);
  EXPECT_EQ(fairAngleMaxima(z, 180, 0.5).size(), 0u);
  expectInvalidParameter([&] { fairAngleMaxima(z, 180, 1.5); }, "alpha_threshold");
  expectInvalidParameter([&] { fairAngleMaxima(z, 180, NAN); }, "alpha_threshold");
  expectInvalidParameter([&] { fairAngleMaxima(z, 3, 0); }, "samples");
  expectInvalidParameter([&] { fairAngleMaxima(z, 180, 0, 0); }, "delta_theta");
}

}  // namespace
}  // namespace fsdb
