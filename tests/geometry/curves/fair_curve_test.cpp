// The fair-curve interpolation of Bernardes, Wu & D'Ottaviano, §2 (geometry/curves/fair_curve.h):
// the curve passes through every point, is G1 there (tangent normal to the radius-vector on both
// sides, same direction), and the radius magnitudes follow the SMOOTHER / SHARPER relations.
#include "geometry/curves/fair_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

std::vector<Vec2> regularPolygon(int n, double radius) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) p.push_back({radius * std::cos(2 * M_PI * i / n), radius * std::sin(2 * M_PI * i / n)});
  return p;
}

// Table 1 of Bernardes, Wu & D'Ottaviano (Figure 1): three points and their radius-vector angles in
// radians.
const std::vector<Vec2> kTable1 = {{100, 440}, {200, 150}, {550, 450}};
const std::vector<double> kTable1Deg = {1.30 * 180 / M_PI, 1.17 * 180 / M_PI, 0.35 * 180 / M_PI};

// A smooth star-shaped closed curve sampled at n points, with some noise, and an open zigzag.
std::vector<Vec2> blob(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + noise(rng)) / n, r = 3 + 0.6 * std::cos(2 * a) + noise(rng);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}
const std::vector<Vec2> kZigzag = {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};

// The unit vector along v (NaN for 0), for any finite v (scaled by a power of two first).
Vec2 direction(const Vec2& v) {
  const int e = std::ilogb(std::max(std::abs(v.x), std::abs(v.y)));
  const Vec2 w{std::ldexp(v.x, -e), std::ldexp(v.y, -e)};
  return (1 / length(w)) * w;
}

void expectInterpolatesAndG1(const FairCurve& c, const std::string& what) {
  const size_t n = c.points.size();
  for (size_t k = 0; k < pieceCount(c); ++k) {
    const size_t b = (k + 1) % n;
    const double scale = length(c.points[b] - c.points[k]);
    EXPECT_LT(length(fairCurvePoint(c, k, 0) - c.points[k]), 1e-9 * scale) << what << " piece " << k;
    EXPECT_LT(length(fairCurvePoint(c, k, 1) - c.points[b]), 1e-9 * scale) << what << " piece " << k;
  }
  // G1 at every joint: both one-sided tangents normal to R_i and pointing the same way.
  for (size_t k = 0; k + 1 < pieceCount(c) || (c.closed && k < pieceCount(c)); ++k) {
    const size_t next = (k + 1) % pieceCount(c), i = (k + 1) % n;
    // Directions first: at scales near 2^±600 products of two lengths leave the double range.
    const Vec2 left = direction(fairCurveDerivative(c, k, 1)), right = direction(fairCurveDerivative(c, next, 0));
    const Vec2 r = direction(c.radii[i]);
    ASSERT_TRUE(std::isfinite(left.x) && std::isfinite(right.x)) << what << " point " << i << ": no tangent";
    EXPECT_NEAR(dot(left, r), 0, 1e-9) << what << " point " << i;
    EXPECT_NEAR(dot(right, r), 0, 1e-9) << what << " point " << i;
    EXPECT_GT(dot(left, right), 0) << what << " point " << i << ": the tangent reverses";
  }
}

TEST(FairCurve, PassesThroughEveryPointWithG1Closed) {
  for (int n : {3, 4, 6, 12}) {
    const auto p = regularPolygon(n, 2);
    expectInterpolatesAndG1(buildFairCurve(p, firstEstimationAngles(p, true), radiusMagnitudes(p, {}, true), true),
                            "polygon " + std::to_string(n));
  }
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const auto p = blob(9, seed);
    const std::vector<Relation> rel = {Relation::kSmoother, Relation::kSharper, Relation::kSmoother,
                                       Relation::kSmoother, Relation::kSharper, Relation::kSharper,
                                       Relation::kSmoother, Relation::kSharper, Relation::kSharper};
    expectInterpolatesAndG1(buildFairCurve(p, firstEstimationAngles(p, true), radiusMagnitudes(p, rel, true), true),
                            "blob " + std::to_string(seed));
  }
}

TEST(FairCurve, PassesThroughEveryPointWithG1Open) {
  expectInterpolatesAndG1(buildFairCurve(kTable1, kTable1Deg, radiusMagnitudes(kTable1, {}, false), false), "table 1");
  const std::vector<Relation> rel = {Relation::kSmoother, Relation::kSharper, Relation::kSharper, Relation::kSmoother};
  expectInterpolatesAndG1(
      buildFairCurve(kZigzag, firstEstimationAngles(kZigzag, false), radiusMagnitudes(kZigzag, rel, false), false),
      "zigzag");
  const std::vector<Vec2> two = {{0, 0}, {3, 1}};
  expectInterpolatesAndG1(buildFairCurve(two, {80, 120}, {1, 2}, false), "two points");
}

TEST(FairCurve, PointsOnACircleGiveANearlyCircularCurve) {
  const auto p = regularPolygon(6, 1);
  const FairCurve c = buildFairCurve(p, firstEstimationAngles(p, true), radiusMagnitudes(p, {}, true), true);
  for (const Vec2& q : sampleFairCurve(c, 65)) EXPECT_NEAR(length(q), 1.0, 0.05);
}

TEST(FairCurve, RadiusMagnitudesFollowTheRelations) {
  const std::vector<Relation> rel = {Relation::kSmoother, Relation::kSmoother, Relation::kSharper, Relation::kSmoother};
  const auto r = radiusMagnitudes(kZigzag, rel, false);
  for (size_t k = 0; k < rel.size(); ++k) {
    const double up = rel[k] == Relation::kSmoother ? r[k + 1] / r[k] : r[k] / r[k + 1];
    EXPECT_NEAR(up, 1.5, 1e-12) << k;
  }
  // Closed: every relation holds strictly, including P_1 against P_N.
  const auto p = regularPolygon(5, 1);
  const std::vector<Relation> closedRel = {Relation::kSmoother, Relation::kSmoother, Relation::kSmoother,
                                           Relation::kSharper, Relation::kSmoother};
  const auto rc = radiusMagnitudes(p, closedRel, true);
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(rc[(k + 1) % 5] > rc[k], closedRel[k] == Relation::kSmoother) << k;
  }
  // No relations: equal magnitudes, the mean chord.
  for (double v : radiusMagnitudes(p, {}, true)) EXPECT_NEAR(v, 2 * std::sin(M_PI / 5), 1e-12);
  // The curve's radius-vectors carry the magnitudes.
  const FairCurve c = buildFairCurve(kZigzag, firstEstimationAngles(kZigzag, false), r, false);
  for (size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(length(c.radii[i]), r[i], 1e-12);
}

TEST(FairCurve, FirstEstimationIsTheBisectorAndEndsTakeTheChordNormal) {
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto a = firstEstimationAngles(square, true);
  EXPECT_NEAR(a[0], 45, 1e-12);
  EXPECT_NEAR(a[1], 135, 1e-12);
  EXPECT_NEAR(a[2], 45, 1e-12);
  EXPECT_NEAR(a[3], 135, 1e-12);
  const auto open = firstEstimationAngles({{0, 0}, {1, 0}, {2, 0}}, false);
  for (double v : open) EXPECT_NEAR(v, 90, 1e-12);  // straight through: the chord normal
}

TEST(FairCurve, SamplesSharePieceEnds) {
  const auto p = regularPolygon(4, 1);
  const FairCurve c = buildFairCurve(p, firstEstimationAngles(p, true), radiusMagnitudes(p, {}, true), true);
  const auto s = sampleFairCurve(c, 9);
  ASSERT_EQ(s.size(), 4u * 8 + 1);
  EXPECT_LT(length(s.front() - s.back()), 1e-9);
  for (size_t k = 0; k < 4; ++k) EXPECT_LT(length(s[8 * k] - p[k]), 1e-9);
  expectInvalidParameter([&] { sampleFairCurve(c, 1); }, "samples");
}

// The construction sees only angles and relative lengths (plane_frame.h): the curve through the
// points scaled by 2^e (and moved) is the original curve scaled (and moved), down to subnormal
// spacings and up to coordinates near the largest double.
TEST(FairCurve, IsTheSameCurveAtEveryScale) {
  const std::vector<Vec2> base = blob(7, 3);
  for (int e : {-1070, -600, -40, 0, 40, 600, 1020}) {
    const Vec2 shift = e == 0 ? Vec2{5, -7} : Vec2{0, 0};
    auto up = [&](const Vec2& p) { return Vec2{std::ldexp(p.x - shift.x, -e), std::ldexp(p.y - shift.y, -e)}; };
    std::vector<Vec2> moved, reference;  // reference: the moved points brought back (exact for e != 0)
    for (const Vec2& p : base) moved.push_back(Vec2{std::ldexp(p.x, e), std::ldexp(p.y, e)} + shift);
    for (const Vec2& p : moved) reference.push_back(up(p));
    const auto angles = firstEstimationAngles(moved, true);
    const auto referenceAngles = firstEstimationAngles(reference, true);
    for (size_t i = 0; i < angles.size(); ++i) EXPECT_NEAR(angles[i], referenceAngles[i], 1e-9) << e;
    const FairCurve c = buildFairCurve(moved, angles, radiusMagnitudes(moved, {}, true), true);
    // Subnormal coordinates keep a few bits: the curve's samples round to multiples of 2^-1074.
    const bool subnormal = e < -1000;
    if (e > -1000 && e < 1000) expectInterpolatesAndG1(c, "scale 2^" + std::to_string(e));
    const std::vector<Vec2> got = sampleFairCurve(c, 9);
    const std::vector<Vec2> want =
        sampleFairCurve(buildFairCurve(reference, referenceAngles, radiusMagnitudes(reference, {}, true), true), 9);
    ASSERT_EQ(got.size(), want.size());
    for (size_t k = 0; k < got.size(); ++k) {
      ASSERT_TRUE(std::isfinite(got[k].x) && std::isfinite(got[k].y)) << e << " sample " << k;
      EXPECT_LT(length(up(got[k]) - want[k]), subnormal ? 0.05 : 1e-9) << e << " sample " << k;
    }
  }
}

// Fuzz findings (tests/fuzz/regressions/curve_document): each gave NaN curve points.
TEST(FairCurve, DegenerateAndExtremePointsGiveFiniteCurves) {
  const std::vector<std::pair<std::vector<Vec2>, bool>> cases = {
      {{{0, 0}, {1, 1}, {2, 2}}, true},             // closed through collinear points: a chord along a radius line
      {{{0, 0}, {5e-324, 0}}, false},               // a subnormal distance
      {{{1e308, 0}, {0, 0}}, false},                // near the largest double
      {{{-1e308, 1e308}, {1e308, -1e308}}, false},  // differences beyond it
  };
  for (const auto& item : cases) {
    const std::vector<Vec2>& points = item.first;  // no structured binding: C++17 lambdas cannot capture one
    const bool closed = item.second;
    if (std::abs(points[0].x) > 1e307 && std::abs(points[0].x - points[1].x) > 1e308) {
      // Points further apart than the largest double have no representable radius: refused.
      expectInvalidParameter([&] { radiusMagnitudes(points, {}, closed); }, "points");
      continue;
    }
    const auto r = radiusMagnitudes(points, {}, closed);
    for (double angle0 = 0; angle0 < 180; angle0 += 15) {
      std::vector<double> angles = firstEstimationAngles(points, closed);
      angles[0] = angle0;
      std::vector<Vec2> got;
      try {
        got = sampleFairCurve(buildFairCurve(points, angles, r, closed), 17);
      } catch (const Error& e) {  // only a curve that leaves the double range may be refused
        EXPECT_EQ(e.path(), "points") << e.what();
        EXPECT_GT(std::abs(points[0].x), 1e307) << e.what();
        continue;
      }
      for (const Vec2& p : got) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << points[0].x << " " << angle0;
    }
  }
}

TEST(FairCurve, RejectsBadInputNamingIt) {
  expectInvalidParameter([] { checkFairPoints({{0, 0}}, false); }, "points");
  expectInvalidParameter([] { checkFairPoints({{0, 0}, {1, 0}}, true); }, "points");
  expectInvalidParameter([] { checkFairPoints({{0, 0}, {1, 0}, {1, 0}}, false); }, "points[2]");
  expectInvalidParameter([] { checkFairPoints({{0, 0}, {1, 0}, {0, 0}}, true); }, "points[0]");
  expectInvalidParameter([] { checkFairPoints({{0, 0}, {NAN, 0}}, false); }, "points[1]");
  expectInvalidParameter([] { radiusMagnitudes(kZigzag, {Relation::kSmoother}, false); }, "relations");
  const auto p = regularPolygon(3, 1);
  expectInvalidParameter(
      [&] {
        radiusMagnitudes(p, {Relation::kSharper, Relation::kSharper, Relation::kSharper}, true);
      },
      "relations");
  expectInvalidParameter([&] { buildFairCurve(p, {0, NAN, 0}, {1, 1, 1}, true); }, "angles[1]");
  expectInvalidParameter([&] { buildFairCurve(p, {0, 0, 0}, {1, 0, 1}, true); }, "magnitudes[1]");
  // Distinct, but not at the size of the curve: 1e300 + 5e-324 rounds to 1e300 once scaled.
  const std::vector<Vec2> far = {{0, 0}, {1e300, 0}, {1e300, 5e-324}};
  expectInvalidParameter([&] { firstEstimationAngles(far, false); }, "points[2]");
  expectInvalidParameter([&] { radiusMagnitudes(far, {}, false); }, "points[2]");
  // A magnitude out of all proportion to the points (1e-300 across 1e300).
  const std::vector<Vec2> big = {{0, 0}, {1e300, 0}, {0, 1e300}};
  expectInvalidParameter([&] { buildFairCurve(big, {0, 0, 0}, {1, 1e-300, 1}, true); }, "magnitudes[1]");
}

TEST(PlaneFrame, MapsPointsToSpreadOneAndBack) {
  for (double s : {5e-324, 1e-310, 1e-200, 1.0, 3e150, 1e300, 1.7e308}) {
    const std::vector<Vec2> points = {{s, -s}, {0.5 * s, 0.25 * s}, {-s, 0}};
    const PlaneFrame f = PlaneFrame::normalizing(points);
    double largest = 0;
    for (const Vec2& p : points) {
      const Vec2 l = f.toLocal(p);
      largest = std::max({largest, std::abs(l.x), std::abs(l.y)});
      const Vec2 back = f.toWorld(l);
      EXPECT_NEAR(back.x, p.x, 1e-15 * s) << s;
      EXPECT_NEAR(back.y, p.y, 1e-15 * s) << s;
    }
    EXPECT_GE(largest, 0.5) << s;
    EXPECT_LT(largest, 1.0) << s;
    EXPECT_DOUBLE_EQ(f.toWorldLength(f.toLocalLength(s)), s);
    EXPECT_DOUBLE_EQ(f.toWorldVector({1, 0}).x, f.toWorldLength(1));
  }
  const PlaneFrame same = PlaneFrame::normalizing({{2, 3}, {2, 3}});
  EXPECT_EQ(same.toLocal({2, 3}).x, 0);
  EXPECT_EQ(same.toWorld({0, 0}).y, 3);
}

}  // namespace
}  // namespace fsdb
