// geometry/field/csg_field and the Booleans of geometry/field/alpha_field.h on analytic fuzzy balls.
#include "geometry/field/csg_field.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/geometry/block_lattice.h"
#include "geometry/core/error.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

std::shared_ptr<const AlphaFieldSource> ball(Vec3 c, double r1, double r2, double r3) {
  return std::make_shared<FuzzyBall>(c, r1, r2, r3);
}

// docs/api.md §3 per level, straight from the set definitions at one α.
bool inUpperAt(CsgOp op, AlphaLevels a, AlphaLevels b, double alpha) {
  switch (op) {
    case CsgOp::kUnion: return inUpper(a, alpha) || inUpper(b, alpha);
    case CsgOp::kIntersection: return inUpper(a, alpha) && inUpper(b, alpha);
    case CsgOp::kDifference: return inUpper(a, alpha) && !inLower(b, alpha);
  }
  return false;
}
bool inLowerAt(CsgOp op, AlphaLevels a, AlphaLevels b, double alpha) {
  switch (op) {
    case CsgOp::kUnion: return inLower(a, alpha) || inLower(b, alpha);
    case CsgOp::kIntersection: return inLower(a, alpha) && inLower(b, alpha);
    case CsgOp::kDifference: return inLower(a, alpha) && !inUpper(b, alpha);
  }
  return false;
}

TEST(CsgField, OperationNamesRoundTrip) {
  for (const CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
    CsgOp back = op == CsgOp::kUnion ? CsgOp::kDifference : CsgOp::kUnion;
    ASSERT_TRUE(csgOpFromName(csgOpName(op), &back)) << csgOpName(op);
    EXPECT_EQ(back, op);
  }
  EXPECT_STREQ(csgOpName(CsgOp::kIntersection), "intersection");
  CsgOp untouched = CsgOp::kUnion;
  EXPECT_FALSE(csgOpFromName("minus", &untouched));
  EXPECT_FALSE(csgOpFromName("Union", &untouched));
  EXPECT_EQ(untouched, CsgOp::kUnion);
}

TEST(CsgField, LevelsAgreeWithThePerLevelSetDefinitionsOfSpec3) {
  auto a = ball({0, 0, 0}, 0.8, 1.0, 1.3), b = ball({1.1, 0, 0}, 0.7, 0.9, 1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1.5, 2.2);
  // Levels the balls' fields cannot hit exactly at random points (measure zero), plus 0 and 1.
  const double alphas[] = {0.0, 0.137, 0.5, 0.77, 1.0};
  for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
    CsgField field(op, {a, b});
    for (int i = 0; i < 20000; ++i) {
      const Vec3 p{coord(rng), coord(rng) * 0.5, coord(rng) * 0.5};
      const AlphaLevels va = a->levelsAt(p), vb = b->levelsAt(p), v = field.levelsAt(p);
      for (double alpha : alphas) {
        if (alpha == 0.0 && (va.upper == 0.0f || vb.upper == 0.0f)) continue;  // the 0-cut's closure
        EXPECT_EQ(inUpper(v, alpha), inUpperAt(op, va, vb, alpha)) << int(op) << " alpha " << alpha;
        EXPECT_EQ(inLower(v, alpha), inLowerAt(op, va, vb, alpha)) << int(op) << " alpha " << alpha;
      }
    }
  }
}

TEST(CsgField, CrispDifferenceRemovesTheOverlapAtEveryLevel) {
  // Crisp balls (r1 = r2 = r3 up to a hair): A − B must not keep A ∩ B at α = 1.
  auto a = ball({0, 0, 0}, 1.0, 1.0, 1.0 + 1e-9), b = ball({1, 0, 0}, 1.0, 1.0, 1.0 + 1e-9);
  CsgField diff(CsgOp::kDifference, {a, b});
  const AlphaLevels overlap = diff.levelsAt({0.5, 0, 0});
  EXPECT_FALSE(inLower(overlap, 1.0));
  EXPECT_FALSE(inUpper(overlap, 1.0));
  const AlphaLevels onlyA = diff.levelsAt({-0.5, 0, 0});
  EXPECT_TRUE(inLower(onlyA, 1.0));
  EXPECT_TRUE(inLower(onlyA, 0.0));
  EXPECT_TRUE(inUpper(onlyA, 1.0));
}

TEST(CsgField, BoundsHoldEveryPointOfTheBoxAndAreUniformFarAway) {
  auto a = ball({0, 0, 0}, 0.8, 1.0, 1.3), b = ball({1.0, 0.2, 0}, 0.5, 0.8, 0.9), c = ball({-0.5, 0, 0.3}, 0.3, 0.4, 0.6);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-2, 2), size(0.01, 0.8), unit(0, 1);
  for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
    CsgField field(op, {a, b, c});
    for (int i = 0; i < 2000; ++i) {
      const Vec3 lo{coord(rng), coord(rng), coord(rng)};
      const Vec3 hi{lo.x + size(rng), lo.y + size(rng), lo.z + size(rng)};
      const AlphaLevelBounds bounds = field.boundsOver(lo, hi);
      for (int k = 0; k < 20; ++k) {
        const Vec3 p{lo.x + unit(rng) * (hi.x - lo.x), lo.y + unit(rng) * (hi.y - lo.y), lo.z + unit(rng) * (hi.z - lo.z)};
        const AlphaLevels v = field.levelsAt(p);
        ASSERT_TRUE(levelsWithin(v, bounds));
      }
    }
    const AlphaLevelBounds far = field.boundsOver({10, 10, 10}, {11, 11, 11});
    EXPECT_TRUE(far.uniform());
    EXPECT_EQ(far.upperMax, 0.0f);
    EXPECT_EQ(far.lowerMin, kNeverInside);
  }
}

TEST(CsgField, BoundingBoxesFollowTheOperation) {
  auto a = ball({0, 0, 0}, 0.5, 1.0, 1.0), b = ball({3, 0, 0}, 0.5, 1.0, 1.0);
  Vec3 lo, hi;
  CsgField(CsgOp::kUnion, {a, b}).boundingBox(&lo, &hi);
  EXPECT_EQ(lo.x, -1.0);
  EXPECT_EQ(hi.x, 4.0);
  CsgField(CsgOp::kDifference, {a, b}).boundingBox(&lo, &hi);
  EXPECT_EQ(hi.x, 1.0);
  CsgField(CsgOp::kIntersection, {a, b}).boundingBox(&lo, &hi);  // disjoint: collapses
  EXPECT_LE(hi.x - lo.x, 0.0);
}

TEST(CsgField, SampleBlockMatchesLevelsAtVoxelByVoxel) {
  auto a = ball({0, 0, 0}, 0.5, 0.8, 1.0), b = ball({0.9, 0, 0}, 0.3, 0.6, 0.7);
  auto c = ball({3, 3, 3}, 0.2, 0.3, 0.4);  // far away: pruned by its bounding box
  const CsgField u(CsgOp::kUnion, {a, b, c}), n(CsgOp::kIntersection, {a, b, c});
  const CsgField m(CsgOp::kDifference, {a, b, c}), nested(CsgOp::kDifference, {std::make_shared<CsgField>(CsgOp::kUnion, std::vector<std::shared_ptr<const AlphaFieldSource>>{a, b, c}), b});
  const double h = 0.05;
  for (const Vec3 first : {Vec3{-1.1, -0.2, -0.2}, Vec3{0.5, -0.1, -0.1}, Vec3{-0.2, -0.2, -0.2},
                           Vec3{0.55, 0.3, -0.1}, Vec3{2.8, 2.8, 2.8}, Vec3{5, 5, 5}})
    for (const CsgField* f : {&u, &n, &m, &nested}) expectBlockMatchesPoints(*f, latticeAt(first, h));
}

TEST(CsgField, NeedsTwoChildren) {
  try {
    CsgField(CsgOp::kUnion, {ball({0, 0, 0}, 1, 1, 1)});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.path(), "children");
  }
}

}  // namespace
}  // namespace fsdb
