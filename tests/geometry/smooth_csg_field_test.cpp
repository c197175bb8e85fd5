// geometry/smooth_csg_field: CSG nodes with smooth operators and blends (seeds 000, 001).
#include "geometry/smooth_csg_field.h"

#include <gtest/gtest.h>

#include <random>

#include "block_lattice.h"
#include "geometry/envelope_grid.h"
#include "geometry/expect_error.h"
#include "geometry/fuzzy_ball.h"
#include "geometry/fuzzy_part_field.h"

namespace fsdb {
namespace {

using Children = std::vector<std::shared_ptr<const AlphaFieldSource>>;

std::shared_ptr<const AlphaFieldSource> crisp(const SuperquadricParams& params, Vec3 at, double scale) {
  PlacedSuperquadric s;
  s.params = params;
  s.placement.translate = at;
  s.placement.scale = scale;
  return std::make_shared<FuzzyPartField>(FuzzyPart::fromCrisp(s));
}
std::shared_ptr<const AlphaFieldSource> sphere(Vec3 at, double r) { return crisp({}, at, r); }
std::shared_ptr<const AlphaFieldSource> box(Vec3 at, double halfSide) {
  SuperquadricParams p;
  p.eps1 = p.eps2 = 0.1;
  return crisp(p, at, halfSide);
}

SmoothCsgField node(CsgOp op, OperatorConfig config, Children children, LeafSmoothing smoothing = {}) {
  return SmoothCsgField(op, config, smoothing, std::move(children));
}

double volumeAtHalf(const AlphaFieldSource& field, double voxel) {
  return EnvelopeGrid::build(field, voxel).volumes({0.5})[0].upper_volume;
}

// Two unit spheres overlapping slightly (centres ±0.95, overlap 0.1; their surfaces cross on the
// circle x = 0, radius 0.312); the default range is 0.1.
Children twoSpheres() { return {sphere({-0.95, 0, 0}, 1.0), sphere({0.95, 0, 0}, 1.0)}; }

// The 0.5 crossing of u along p0 + t·dir, t in [t0, t1] (u falls from >= 0.5 to < 0.5).
double halfLevelCrossing(const AlphaFieldSource& f, Vec3 p0, Vec3 dir, double t0, double t1) {
  for (int i = 0; i < 60; ++i) {
    const double t = 0.5 * (t0 + t1);
    (f.levelsAt(p0 + dir * t).upper >= 0.5f ? t0 : t1) = t;
  }
  return t0;
}

TEST(SmoothCsgField, BlendedUnionsFillTheNeckAndKeepTheSurfacesElsewhere) {
  const SmoothCsgField zadeh = node(CsgOp::kUnion, {"zadeh", {}, {}}, twoSpheres());
  const double zadehVolume = volumeAtHalf(zadeh, 0.04);
  EXPECT_NEAR(zadehVolume, 2 * 4.18879 - 0.0154, 0.1);  // minus the lens π(4 + 1.9)(0.1)²/12
  for (const OperatorConfig& config : {OperatorConfig{"bezier", {{"n", 3.0}}, {}},
                                       OperatorConfig{"smooth_and", {{"n", 2.0}, {"delta", 0.5}}, {}}}) {
    const SmoothCsgField blended = node(CsgOp::kUnion, config, twoSpheres());
    for (double y : {0.33, 0.37, 0.42})  // the crease of the neck, outside both spheres
      EXPECT_GT(blended.levelsAt({0, y, 0}).upper, zadeh.levelsAt({0, y, 0}).upper + 1e-3) << config.name << " " << y;
    // Far from the neck the 0.5 level is each sphere's surface (x = 2.05, and y = 1 above a
    // centre), well within a voxel.
    EXPECT_NEAR(halfLevelCrossing(blended, {0.95, 0, 0}, {1, 0, 0}, 0.5, 1.2), 1.0, 1e-3) << config.name;
    EXPECT_NEAR(halfLevelCrossing(blended, {-0.95, 0, 0}, {0, 1, 0}, 0.5, 1.2), 1.0, 1e-3) << config.name;
    // The volume at 0.5 grows, only by the neck: outside both spheres both memberships are > 0
    // only within 0.1 of both (|x| < 0.1, radius in [0.312, 0.554]: a ring of volume < 0.13).
    const double increase = volumeAtHalf(blended, 0.04) - zadehVolume;
    EXPECT_GT(increase, 0.0) << config.name;
    EXPECT_LT(increase, 0.13) << config.name;
  }
}

// Two unit boxes overlapping in an L (seed 001 §3: exterior blending contains both operands,
// the interior blended union is a subset of the union).
Children twoBoxes() { return {box({0, 0, 0}, 1.0), box({1.5, 1.5, 0}, 1.0)}; }

TEST(SmoothCsgField, ExtMaxUnionContainsTheOperandsAndIntMaxUnionLiesInside) {
  const LeafSmoothing range{0.3, {"polynomial", {{"n", 3.0}}, {}}};
  const SmoothCsgField zadeh = node(CsgOp::kUnion, {"zadeh", {}, {}}, twoBoxes(), range);
  const SmoothCsgField ext = node(CsgOp::kUnion, {"ext_max", {{"delta", 0.4}, {"epsilon", 0.2}}, {}}, twoBoxes(), range);
  const SmoothCsgField in = node(CsgOp::kUnion, {"int_max", {{"epsilon", 1.0}}, {}}, twoBoxes(), range);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> c(-1.3, 2.8);
  int above = 0, below = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p{c(rng), c(rng), c(rng) * 0.5};
    const float z = zadeh.levelsAt(p).upper, e = ext.levelsAt(p).upper, n = in.levelsAt(p).upper;
    ASSERT_GE(e, z);
    ASSERT_LE(n, z);
    above += e > z;
    below += n < z;
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(below, 0);
  const double zv = volumeAtHalf(zadeh, 0.05), ev = volumeAtHalf(ext, 0.05), iv = volumeAtHalf(in, 0.05);
  EXPECT_GT(ev, zv);
  EXPECT_LT(iv, zv);
  EXPECT_NEAR(zv, 8.0 + 8.0 - 0.25 * 2, 0.3);  // two boxes of 8 minus their 0.5 x 0.5 x 2 overlap
}

TEST(SmoothCsgField, AlgebraicIntersectionOfFuzzyPartsLiesBelowZadeh) {
  FuzzyPart fuzzy;
  fuzzy.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  const Children children{std::make_shared<FuzzyPartField>(fuzzy), std::make_shared<FuzzyBall>(Vec3{0.9, 0, 0}, 0.7, 0.9, 1.1)};
  const CsgField zadeh(CsgOp::kIntersection, children);
  const SmoothCsgField algebraic = node(CsgOp::kIntersection, {"algebraic", {}, {}}, children);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> c(-0.5, 1.5);
  int strictly = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p{c(rng), c(rng) * 0.6, c(rng) * 0.6};
    const AlphaLevels z = zadeh.levelsAt(p), a = algebraic.levelsAt(p);
    ASSERT_LE(a.upper, z.upper);  // x·y <= min(x, y)
    ASSERT_LE(necessityOf(a), necessityOf(z) + 1e-6);
    strictly += a.upper < z.upper;
  }
  EXPECT_GT(strictly, 30);
}

TEST(SmoothCsgField, ZadehNodeOfFuzzySolidsIsTheCsgFieldForThreeChildren) {
  const Children balls{std::make_shared<FuzzyBall>(Vec3{0, 0, 0}, 0.8, 1.0, 1.3),
                       std::make_shared<FuzzyBall>(Vec3{1.1, 0, 0}, 0.7, 0.9, 1.0),
                       std::make_shared<FuzzyBall>(Vec3{0.5, 0.6, 0}, 0.3, 0.5, 0.6)};
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> c(-1.5, 2.2);
  for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
    const CsgField exact(op, balls);
    const SmoothCsgField ours = node(op, {"zadeh", {}, {}}, balls);
    for (int i = 0; i < 5000; ++i) {
      const Vec3 p{c(rng), c(rng), c(rng)};
      const AlphaLevels e = exact.levelsAt(p), o = ours.levelsAt(p);
      ASSERT_EQ(o.upper, e.upper);
      ASSERT_EQ(o.lower, e.lower == 1.0f ? kNeverInside : e.lower);
    }
  }
}

TEST(SmoothCsgField, BoundsAndBoundingBoxAreSound) {
  for (const char* name : {"bezier", "ext_max", "int_max"}) {
    for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
      const SmoothCsgField f = node(op, {name, {}, {}}, twoSpheres(), {0.3, {"polynomial", {}, {}}});
      Vec3 blo, bhi;
      f.boundingBox(&blo, &bhi);
      std::mt19937 rng(6);
      std::uniform_real_distribution<double> c(-3.0, 3.0), w(0.0, 0.8), t(0.0, 1.0);
      for (int i = 0; i < 400; ++i) {
        const Vec3 lo{c(rng), c(rng) * 0.6, c(rng) * 0.6}, hi = lo + Vec3{w(rng), w(rng), w(rng)};
        const AlphaLevelBounds b = f.boundsOver(lo, hi);
        for (int k = 0; k < 10; ++k) {
          const Vec3 p{lo.x + t(rng) * (hi.x - lo.x), lo.y + t(rng) * (hi.y - lo.y), lo.z + t(rng) * (hi.z - lo.z)};
          const AlphaLevels v = f.levelsAt(p);
          ASSERT_TRUE(levelsWithin(v, b)) << name;
          const bool outside = p.x < blo.x || p.y < blo.y || p.z < blo.z || p.x > bhi.x || p.y > bhi.y || p.z > bhi.z;
          if (outside) {
            ASSERT_EQ(v.upper, 0.0f) << name;
          }
        }
      }
      // Far from both spheres every operator proves the block empty.
      EXPECT_TRUE(f.boundsOver({5, 5, 5}, {6, 6, 6}).uniform()) << name;
    }
  }
}

TEST(SmoothCsgField, SmoothsCrispPartsBelowZadehNodesAndKeepsFuzzyOnes) {
  FuzzyPart fuzzy;
  fuzzy.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  fuzzy.tx = FuzzyNumber::crisp(-3.0);  // away from the crisp spheres
  const auto fuzzyLeaf = std::make_shared<FuzzyPartField>(fuzzy);
  const auto zadehNode = std::make_shared<CsgField>(CsgOp::kDifference, Children{sphere({2, 0, 0}, 1.0), sphere({2.5, 0, 0}, 0.5)});
  const SmoothCsgField f = node(CsgOp::kUnion, {"algebraic", {}, {}}, {fuzzyLeaf, zadehNode});
  EXPECT_EQ(f.children()[0], fuzzyLeaf);
  const auto* below = dynamic_cast<const CsgField*>(f.children()[1].get());
  ASSERT_NE(below, nullptr);
  for (const auto& c : below->children()) EXPECT_NE(dynamic_cast<const SmoothedPartField*>(c.get()), nullptr);
  // The Zadeh difference keeps each surface as its 0.5 level: x = 1 (left of the first sphere)
  // and x = 2 (the second sphere's face, seen from inside the difference).
  EXPECT_NEAR(halfLevelCrossing(f, {1.5, 0, 0}, {-1, 0, 0}, 0.0, 1.0), 0.5, 1e-3);
  EXPECT_NEAR(halfLevelCrossing(f, {1.5, 0, 0}, {1, 0, 0}, 0.0, 0.9), 0.5, 1e-3);
  EXPECT_EQ(smoothCrispParts(fuzzyLeaf, {}), fuzzyLeaf);
}

TEST(SmoothCsgField, RefusesBadNodes) {
  expectInvalidParameter([] { node(CsgOp::kUnion, {"bezier", {{"n", 0.0}}, {}}, twoSpheres()); }, "operator.n");
  expectInvalidParameter([] { node(CsgOp::kUnion, {"polynomial", {}, {}}, twoSpheres()); }, "operator.name");
  expectInvalidParameter([] { node(CsgOp::kUnion, {"bezier", {}, {}}, twoSpheres(), {{}, {"sigmoid", {{"epsilon", 3.0}}, {}}}); },
                         "step.epsilon");
  expectInvalidParameter([] { node(CsgOp::kUnion, {"bezier", {}, {}}, twoSpheres(), {0.0, {"polynomial", {}, {}}}); },
                         "range");
  // Checked even where no crisp part takes it.
  expectInvalidParameter(
      [] {
        node(CsgOp::kUnion, {"bezier", {}, {}},
             {std::make_shared<FuzzyBall>(Vec3{0, 0, 0}, 1, 1, 1), std::make_shared<FuzzyBall>(Vec3{1, 0, 0}, 1, 1, 1)},
             {-2.0, {"polynomial", {}, {}}});
      },
      "range");
  try {
    node(CsgOp::kUnion, {"bezier", {}, {}}, {sphere({0, 0, 0}, 1)});
    ADD_FAILURE() << "one child accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidDocument);
    EXPECT_EQ(e.path(), "children");
  }
}

}  // namespace
}  // namespace fsdb
