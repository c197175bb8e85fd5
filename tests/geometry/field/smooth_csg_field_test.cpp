// geometry/field/smooth_csg_field: CSG nodes with smooth operators and blends (Li & Tian; Li), in
// the membership world (crisp parts only) and the (Π, N) world.
#include "geometry/field/smooth_csg_field.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "tests/geometry/block_lattice.h"
#include "geometry/voxel/envelope_grid.h"
#include "geometry/voxel/envelope_grid_vdb.h"
#include "tests/geometry/expect_error.h"
#include "tests/geometry/fuzzy_ball.h"
#include "geometry/field/fuzzy_part_field.h"
#include "tests/geometry/operator_names.h"

namespace fsdb {
namespace {

using Field = std::shared_ptr<const AlphaFieldSource>;
using Children = std::vector<Field>;

std::shared_ptr<const FuzzyPartField> crisp(const SuperquadricParams& params, Vec3 at, double scale) {
  PlacedSuperquadric s;
  s.params = params;
  s.placement.translate = at;
  s.placement.scale = scale;
  return std::make_shared<FuzzyPartField>(FuzzyPart::fromCrisp(s));
}
std::shared_ptr<const FuzzyPartField> sphere(Vec3 at, double r) { return crisp({}, at, r); }
std::shared_ptr<const FuzzyPartField> box(Vec3 at, double halfSide) {
  SuperquadricParams p;
  p.eps1 = p.eps2 = 0.1;
  return crisp(p, at, halfSide);
}

Field node(CsgOp op, OperatorConfig config, Children children, LeafSmoothing smoothing = {}) {
  return makeSmoothCsgNode(op, std::move(config), smoothing, std::move(children));
}
// The node of crisp parts only: a membership field.
std::shared_ptr<const MembershipCsgField> membershipNode(CsgOp op, OperatorConfig config, Children children,
                                                         LeafSmoothing smoothing = {}) {
  auto f = std::dynamic_pointer_cast<const MembershipCsgField>(node(op, std::move(config), std::move(children), smoothing));
  EXPECT_NE(f, nullptr);
  return f;
}

LevelVolume volumeAt(const AlphaFieldSource& field, double voxel, double alpha) {
  return EnvelopeGrid::build(field, voxel).volumes({alpha})[0];
}

// Two unit spheres overlapping slightly (centres ±0.95, overlap 0.1; their surfaces cross on the
// circle x = 0, radius 0.312); the default range is 0.1.
Children twoSpheres() { return {sphere({-0.95, 0, 0}, 1.0), sphere({0.95, 0, 0}, 1.0)}; }

// Where along p0 + t·dir, t in [t0, t1], the point leaves the core (u = 1: the α = 1 shape,
// membership >= 1/2 in the membership world).
double coreCrossing(const AlphaFieldSource& f, Vec3 p0, Vec3 dir, double t0, double t1) {
  for (int i = 0; i < 60; ++i) {
    const double t = 0.5 * (t0 + t1);
    (f.levelsAt(p0 + dir * t).upper >= 1.0f ? t0 : t1) = t;
  }
  return t0;
}

// Li & Tian, §3: a smooth union of crisp parts is the 0.5 level of the blended membership; fsdb
// reads it at α = 1, where lower and upper are that one shape.
TEST(SmoothCsgField, BlendedUnionsFillTheNeckAndKeepTheSurfacesElsewhere) {
  const auto zadeh = membershipNode(CsgOp::kUnion, {"zadeh", {}, {}}, twoSpheres());
  const LevelVolume zadehVolume = volumeAt(*zadeh, 0.04, 1.0);
  EXPECT_NEAR(zadehVolume.upper_volume, 2 * 4.18879 - 0.0154, 0.1);  // minus the lens π(4 + 1.9)(0.1)²/12
  for (const OperatorConfig& config : {OperatorConfig{"bezier", {{"n", 3.0}}, {}},
                                       OperatorConfig{"smooth_and", {{"n", 2.0}, {"delta", 0.5}}, {}}}) {
    const auto blended = membershipNode(CsgOp::kUnion, config, twoSpheres());
    for (double y : {0.33, 0.37, 0.42})  // the crease of the neck, outside both spheres
      EXPECT_GT(blended->membership({0, y, 0}), zadeh->membership({0, y, 0}) + 1e-3) << config.name << " " << y;
    // The crease is filled at α = 1: just outside both spheres, inside the blended shape.
    EXPECT_LT(zadeh->levelsAt({0, 0.33, 0}).upper, 1.0f);
    EXPECT_EQ(blended->levelsAt({0, 0.33, 0}).upper, 1.0f) << config.name;
    // Far from the neck the core's surface is each sphere's surface (x = 2.05, and y = 1 above a
    // centre), well within a voxel.
    EXPECT_NEAR(coreCrossing(*blended, {0.95, 0, 0}, {1, 0, 0}, 0.5, 1.2), 1.0, 1e-3) << config.name;
    EXPECT_NEAR(coreCrossing(*blended, {-0.95, 0, 0}, {0, 1, 0}, 0.5, 1.2), 1.0, 1e-3) << config.name;
    // The volume at α = 1 grows, only by the neck: outside both spheres both memberships are > 0
    // only within 0.1 of both (|x| < 0.1, radius in [0.312, 0.554]: a ring of volume < 0.13).
    const LevelVolume v = volumeAt(*blended, 0.04, 1.0);
    EXPECT_GT(v.upper_volume - zadehVolume.upper_volume, 0.0) << config.name;
    EXPECT_LT(v.upper_volume - zadehVolume.upper_volume, 0.13) << config.name;
    EXPECT_NEAR(v.lower_volume, v.upper_volume, 1e-3 * v.upper_volume) << config.name;  // one shape
  }
}

// The α = 1 shape of a crisp-only smooth union is exactly Li & Tian's {μ' >= 1/2}, μ' = S(μA, μB)
// of the smoothed parts: the grid's core voxels are the lattice points with μ' >= 1/2, and the
// fuzzy volume nests around it (lower grows, upper shrinks with α; lower <= upper).
TEST(SmoothCsgField, CrispOnlySmoothUnionCoreIsTheHalfLevelOfTheBlendedMembership) {
  const LeafSmoothing smoothing{0.2, {"polynomial", {{"n", 3.0}}, {}}};
  const Children spheres = twoSpheres();
  const SmoothedPartField a(std::static_pointer_cast<const FuzzyPartField>(spheres[0]), smoothing);
  const SmoothedPartField b(std::static_pointer_cast<const FuzzyPartField>(spheres[1]), smoothing);
  for (const char* name : {"bezier", "algebraic", "ext_max", "int_max"}) {
    const NodeOperator op({name, {}, {}});
    const auto f = membershipNode(CsgOp::kUnion, {name, {}, {}}, spheres, smoothing);
    const double h = 0.05;
    const EnvelopeGrid grid = EnvelopeGrid::build(*f, h);
    // Brute force over the grid's lattice (voxel centres (i + 1/2)·h) around the bounding box.
    Vec3 lo, hi;
    f->boundingBox(&lo, &hi);
    long core = 0;
    for (int i = int(std::floor(lo.x / h)) - 1; i <= int(std::ceil(hi.x / h)) + 1; ++i)
      for (int j = int(std::floor(lo.y / h)) - 1; j <= int(std::ceil(hi.y / h)) + 1; ++j)
        for (int k = int(std::floor(lo.z / h)) - 1; k <= int(std::ceil(hi.z / h)) + 1; ++k) {
          const Vec3 p{(i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h};
          core += op.combine(CsgOp::kUnion, a.membership(p), b.membership(p)) >= 0.5;
        }
    std::vector<double> alphas;
    for (int i = 0; i <= 16; ++i) alphas.push_back(i / 16.0);
    const std::vector<LevelVolume> v = grid.volumes(alphas);
    EXPECT_DOUBLE_EQ(v.back().upper_volume, core * h * h * h) << name;
    EXPECT_NEAR(v.back().lower_volume, v.back().upper_volume, 1e-3 * v.back().upper_volume) << name;
    for (size_t i = 0; i < v.size(); ++i) {
      EXPECT_LE(v[i].lower_volume, v[i].upper_volume) << name << " " << alphas[i];
      if (i == 0) continue;
      EXPECT_GE(v[i].lower_volume, v[i - 1].lower_volume) << name << " " << alphas[i];
      EXPECT_LE(v[i].upper_volume, v[i - 1].upper_volume) << name << " " << alphas[i];
    }
    EXPECT_LT(v[8].lower_volume, v.back().lower_volume) << name;  // a real interval below α = 1
    EXPECT_GT(v[8].upper_volume, v.back().upper_volume) << name;
  }
}

// Two unit boxes overlapping in an L (Li, §3: exterior blending contains both operands,
// the interior blended union is a subset of the union), at α = 1.
Children twoBoxes() { return {box({0, 0, 0}, 1.0), box({1.5, 1.5, 0}, 1.0)}; }

TEST(SmoothCsgField, ExtMaxUnionContainsTheOperandsAndIntMaxUnionLiesInside) {
  const LeafSmoothing range{0.3, {"polynomial", {{"n", 3.0}}, {}}};
  const auto zadeh = membershipNode(CsgOp::kUnion, {"zadeh", {}, {}}, twoBoxes(), range);
  const auto ext = membershipNode(CsgOp::kUnion, {"ext_max", {{"delta", 0.4}, {"epsilon", 0.2}}, {}}, twoBoxes(), range);
  const auto in = membershipNode(CsgOp::kUnion, {"int_max", {{"epsilon", 1.0}}, {}}, twoBoxes(), range);
  const Children boxes = twoBoxes();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> c(-1.3, 2.8);
  int above = 0, below = 0, inOperand = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p{c(rng), c(rng), c(rng) * 0.5};
    const double z = zadeh->membership(p), e = ext->membership(p), n = in->membership(p);
    ASSERT_GE(e, z);
    ASSERT_LE(n, z);
    above += e > z;
    below += n < z;
    // The cores: an operand (the crisp box) lies in ext_max's core; int_max's core in an operand.
    const bool operand = boxes[0]->levelsAt(p).upper == 1.0f || boxes[1]->levelsAt(p).upper == 1.0f;
    inOperand += operand;
    if (operand) {
      ASSERT_EQ(ext->levelsAt(p).upper, 1.0f);
    }
    if (in->levelsAt(p).upper == 1.0f) {
      ASSERT_TRUE(operand || zadeh->levelsAt(p).upper == 1.0f);
    }
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(below, 0);
  EXPECT_GT(inOperand, 1000);
  const double zv = volumeAt(*zadeh, 0.05, 1.0).upper_volume, ev = volumeAt(*ext, 0.05, 1.0).upper_volume,
               iv = volumeAt(*in, 0.05, 1.0).upper_volume;
  EXPECT_GT(ev, zv);
  EXPECT_LT(iv, zv);
  EXPECT_NEAR(zv, 8.0 + 8.0 - 0.25 * 2, 0.3);  // two boxes of 8 minus their 0.5 x 0.5 x 2 overlap
}

TEST(SmoothCsgField, AlgebraicIntersectionOfFuzzyPartsLiesBelowZadeh) {
  FuzzyPart fuzzy;
  fuzzy.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  const Children children{std::make_shared<FuzzyPartField>(fuzzy), std::make_shared<FuzzyBall>(Vec3{0.9, 0, 0}, 0.7, 0.9, 1.1)};
  const CsgField zadeh(CsgOp::kIntersection, children);
  const Field algebraic = node(CsgOp::kIntersection, {"algebraic", {}, {}}, children);
  ASSERT_NE(dynamic_cast<const SmoothCsgField*>(algebraic.get()), nullptr);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> c(-0.5, 1.5);
  int strictly = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p{c(rng), c(rng) * 0.6, c(rng) * 0.6};
    const AlphaLevels z = zadeh.levelsAt(p), a = algebraic->levelsAt(p);
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
    const Field ours = node(op, {"zadeh", {}, {}}, balls);
    for (int i = 0; i < 5000; ++i) {
      const Vec3 p{c(rng), c(rng), c(rng)};
      const AlphaLevels e = exact.levelsAt(p), o = ours->levelsAt(p);
      ASSERT_EQ(o.upper, e.upper);
      ASSERT_EQ(o.lower, e.lower == 1.0f ? kNeverInside : e.lower);
    }
  }
}

// Zadeh's min/max commute with the map of membership_field.h: on crisp parts the zadeh
// membership node has the levels of the zadeh Booleans of the smoothed parts' pairs (to float
// rounding).
TEST(SmoothCsgField, ZadehMembershipNodeHasTheLevelsOfTheBooleansOfItsChildren) {
  const LeafSmoothing smoothing{0.3, {"polynomial", {}, {}}};
  const Children spheres = twoSpheres();
  const Children smoothed{smoothCrispParts(spheres[0], smoothing), smoothCrispParts(spheres[1], smoothing)};
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> c(-2.4, 2.4);
  for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
    const auto membership = membershipNode(op, {"zadeh", {}, {}}, spheres, smoothing);
    const CsgField pairs(op, smoothed);
    for (int i = 0; i < 5000; ++i) {
      const Vec3 p{c(rng), c(rng) * 0.5, c(rng) * 0.5};
      // Equal up to the float rounding of 1 − μ, 2μ and 2 − 2μ (an ulp of 1).
      const AlphaLevels m = membership->levelsAt(p), e = pairs.levelsAt(p);
      ASSERT_NEAR(possibilityOf(m), possibilityOf(e), 2e-7) << int(op);
      ASSERT_NEAR(necessityOf(m), necessityOf(e), 2e-7) << int(op);
    }
  }
}

TEST(SmoothCsgField, BoundsAndBoundingBoxAreSound) {
  for (const char* name : {"bezier", "ext_max", "int_max"}) {
    for (CsgOp op : {CsgOp::kUnion, CsgOp::kIntersection, CsgOp::kDifference}) {
      const auto f = membershipNode(op, {name, {}, {}}, twoSpheres(), {0.3, {"polynomial", {}, {}}});
      Vec3 blo, bhi;
      f->boundingBox(&blo, &bhi);
      std::mt19937 rng(6);
      std::uniform_real_distribution<double> c(-3.0, 3.0), w(0.0, 0.8), t(0.0, 1.0);
      for (int i = 0; i < 400; ++i) {
        const Vec3 lo{c(rng), c(rng) * 0.6, c(rng) * 0.6}, hi = lo + Vec3{w(rng), w(rng), w(rng)};
        const AlphaLevelBounds b = f->boundsOver(lo, hi);
        const MembershipRange m = f->membershipOver(lo, hi);
        for (int k = 0; k < 10; ++k) {
          const Vec3 p{lo.x + t(rng) * (hi.x - lo.x), lo.y + t(rng) * (hi.y - lo.y), lo.z + t(rng) * (hi.z - lo.z)};
          const AlphaLevels v = f->levelsAt(p);
          ASSERT_TRUE(levelsWithin(v, b)) << name;
          ASSERT_GE(f->membership(p), m.lo) << name;
          ASSERT_LE(f->membership(p), m.hi) << name;
          const bool outside = p.x < blo.x || p.y < blo.y || p.z < blo.z || p.x > bhi.x || p.y > bhi.y || p.z > bhi.z;
          if (outside) {
            ASSERT_EQ(f->membership(p), 0.0) << name;
          }
        }
      }
      // Far from both spheres every operator proves the block empty.
      EXPECT_TRUE(f->boundsOver({5, 5, 5}, {6, 6, 6}).uniform()) << name;
    }
  }
}

TEST(SmoothCsgField, SmoothsCrispPartsBelowZadehNodesAndKeepsFuzzyOnes) {
  FuzzyPart fuzzy;
  fuzzy.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  fuzzy.tx = FuzzyNumber::crisp(-3.0);  // away from the crisp spheres
  const auto fuzzyLeaf = std::make_shared<FuzzyPartField>(fuzzy);
  const auto zadehNode = std::make_shared<CsgField>(CsgOp::kDifference, Children{sphere({2, 0, 0}, 1.0), sphere({2.5, 0, 0}, 0.5)});
  const Field f = node(CsgOp::kUnion, {"algebraic", {}, {}}, {fuzzyLeaf, zadehNode});
  const auto* pairs = dynamic_cast<const SmoothCsgField*>(f.get());  // a fuzzy child: the (Π, N) world
  ASSERT_NE(pairs, nullptr);
  EXPECT_EQ(pairs->children()[0], fuzzyLeaf);
  // The zadeh node of crisp parts combines their memberships.
  const auto* below = dynamic_cast<const MembershipCsgField*>(pairs->children()[1].get());
  ASSERT_NE(below, nullptr);
  EXPECT_EQ(below->nodeOperator().config().name, "zadeh");
  for (const auto& c : below->children()) EXPECT_NE(dynamic_cast<const SmoothedPartField*>(c.get()), nullptr);
  // The Zadeh difference keeps each surface as its core's boundary: x = 1 (left of the first
  // sphere) and x = 2 (the second sphere's face, seen from inside the difference).
  EXPECT_NEAR(coreCrossing(*f, {1.5, 0, 0}, {-1, 0, 0}, 0.0, 1.0), 0.5, 1e-3);
  EXPECT_NEAR(coreCrossing(*f, {1.5, 0, 0}, {1, 0, 0}, 0.0, 0.9), 0.5, 1e-3);
  EXPECT_EQ(smoothCrispParts(fuzzyLeaf, {}), fuzzyLeaf);
  // A zadeh node with a fuzzy child stays a CsgField (of the smoothed crisp part and the fuzzy one).
  const Field mixed = smoothCrispParts(std::make_shared<CsgField>(CsgOp::kUnion, Children{fuzzyLeaf, sphere({2, 0, 0}, 1.0)}), {});
  const auto* mixedCsg = dynamic_cast<const CsgField*>(mixed.get());
  ASSERT_NE(mixedCsg, nullptr);
  EXPECT_NE(dynamic_cast<const SmoothedPartField*>(mixedCsg->children()[1].get()), nullptr);
}

// Li & Tian's blends of blends: a smooth node over a smooth node of crisp parts combines
// memberships all the way; a fuzzy child turns the node into the pair world, where the membership
// child enters as its pair.
TEST(SmoothCsgField, NestedMembershipsCombineAndMeetPairsThroughTheMap) {
  const LeafSmoothing smoothing{0.2, {"polynomial", {}, {}}};
  const NodeOperator bezier({"bezier", {}, {}});
  const auto inner = membershipNode(CsgOp::kUnion, {"bezier", {}, {}}, twoSpheres(), smoothing);
  const auto third = sphere({0, 0.9, 0}, 0.6);
  const auto outer = membershipNode(CsgOp::kDifference, {"bezier", {}, {}}, {inner, third}, smoothing);
  const SmoothedPartField thirdSmoothed(third, smoothing);
  const auto ball = std::make_shared<FuzzyBall>(Vec3{0, -0.8, 0}, 0.4, 0.6, 0.8);
  const Field mixed = node(CsgOp::kUnion, {"bezier", {}, {}}, {inner, ball}, smoothing);
  ASSERT_NE(dynamic_cast<const SmoothCsgField*>(mixed.get()), nullptr);
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> c(-2.2, 2.2);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p{c(rng), c(rng) * 0.8, c(rng) * 0.6};
    ASSERT_EQ(outer->membership(p), bezier.combine(CsgOp::kDifference, inner->membership(p), thirdSmoothed.membership(p)));
    const AlphaLevels m = mixed->levelsAt(p), e = bezier.combine(CsgOp::kUnion, levelsFromMembership(inner->membership(p)), ball->levelsAt(p));
    ASSERT_EQ(m.upper, e.upper);
    ASSERT_EQ(m.lower, e.lower);
  }
}

// In the (Π, N) world the core blends only where the operator reaches 1 with both arguments
// below 1: lukasiewicz's min(1, x + y) fills the crease at α = 1, bezier's strict conorm does not
// (its core is the union of the children's cores).
TEST(SmoothCsgField, PairNodesBlendTheCoreOnlyWhereTheOperatorReachesOne) {
  const Children children{sphere({-0.95, 0, 0}, 1.0), std::make_shared<FuzzyBall>(Vec3{0.95, 0, 0}, 0.8, 1.0, 1.3)};
  const Field lukasiewicz = node(CsgOp::kUnion, {"lukasiewicz", {}, {}}, children);
  const Field bezier = node(CsgOp::kUnion, {"bezier", {}, {}}, children);
  ASSERT_NE(dynamic_cast<const SmoothCsgField*>(bezier.get()), nullptr);
  const Vec3 crease{0, 0.33, 0};  // outside the sphere and outside the ball's core
  EXPECT_LT(children[1]->levelsAt(crease).upper, 1.0f);
  EXPECT_EQ(lukasiewicz->levelsAt(crease).upper, 1.0f);
  EXPECT_LT(bezier->levelsAt(crease).upper, 1.0f);
  EXPECT_GT(bezier->levelsAt(crease).upper, children[1]->levelsAt(crease).upper);  // blended below α = 1
}

// A random tree of crisp and fuzzy leaves (crisp superquadric parts, fuzzy superquadric parts,
// fuzzy balls) and nodes with random operators of the catalogue (zadeh nodes as CsgField).
class RandomTrees {
 public:
  explicit RandomTrees(unsigned seed) : rng_(seed) {}

  // With crispOnly every leaf is a crisp part (so smooth nodes are membership nodes).
  Field tree(int depth, const std::string& name, bool crispOnly) {
    if (depth == 0 || unit() < 0.25) return leaf(crispOnly);
    const CsgOp op = CsgOp(std::uniform_int_distribution<int>(0, 2)(rng_));
    Children children;
    const int n = unit() < 0.7 ? 2 : 3;
    for (int i = 0; i < n; ++i) children.push_back(tree(depth - 1, unit() < 0.7 ? name : names_[pick(names_.size())], crispOnly));
    if (name == "zadeh") return std::make_shared<CsgField>(op, std::move(children));
    LeafSmoothing smoothing;
    if (unit() < 0.5) smoothing.range = 0.05 + 0.3 * unit();
    if (unit() < 0.3) smoothing.step = {"bspline", {{"m", 3.0}}, {}};
    return makeSmoothCsgNode(op, {name, {}, {}}, smoothing, std::move(children));
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  size_t pick(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng_); }
  Vec3 at() { return {unit() * 1.6 - 0.8, unit() * 1.6 - 0.8, unit() * 1.2 - 0.6}; }

  Field leaf(bool crispOnly) {
    const double kind = crispOnly ? 0.0 : unit();
    if (kind < 0.45) {
      SuperquadricParams q;
      q.eps1 = 0.3 + 1.5 * unit();
      q.eps2 = 0.3 + 1.5 * unit();
      q.a2 = 0.6 + 0.6 * unit();
      q.kx = unit() < 0.3 ? unit() - 0.5 : 0.0;
      return crisp(q, at(), 0.4 + 0.5 * unit());
    }
    if (kind < 0.55) {
      FuzzyPart f;
      const double r = 0.4 + 0.4 * unit();
      f.a1 = FuzzyNumber::triangular(0.8 * r, r, 1.2 * r);
      const Vec3 c = at();
      f.tx = FuzzyNumber::triangular(c.x - 0.1, c.x, c.x + 0.1);
      f.ty = FuzzyNumber::crisp(c.y);
      f.tz = FuzzyNumber::crisp(c.z);
      return std::make_shared<FuzzyPartField>(f);
    }
    const double r2 = 0.4 + 0.5 * unit();
    return std::make_shared<FuzzyBall>(at(), r2 * (0.5 + 0.5 * unit()), r2, r2 * (1 + 0.5 * unit()));
  }

  std::mt19937 rng_;
  std::vector<std::string> names_ = binaryOperatorNames();
};

// docs/api.md §3 on random smooth trees, every operator of the catalogue: lower(α) ⊆ upper(α) at
// sample points (nesting in α holds for any pair), the bounds hold the points of their box, and
// on the voxel grid every voxel and tile keeps it and the volumes nest.
TEST(SmoothCsgField, RandomSmoothTreesKeepLowerInsideUpperAndNest) {
  RandomTrees trees(2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> c(-1.8, 1.8), w(0.0, 0.5), t(0.0, 1.0);
  std::vector<double> alphas;
  for (int i = 0; i <= 8; ++i) alphas.push_back(i / 8.0);
  long necessary = 0, partly = 0, membershipTrees = 0;
  for (const std::string& name : binaryOperatorNames()) {
    for (int k = 0; k < 8; ++k) {
      const Field f = trees.tree(3, name, k % 2 == 0);
      membershipTrees += dynamic_cast<const MembershipField*>(f.get()) != nullptr;
      for (int i = 0; i < 150; ++i) {
        const Vec3 lo{c(rng), c(rng), c(rng)}, hi = lo + Vec3{w(rng), w(rng), w(rng)};
        const AlphaLevelBounds b = f->boundsOver(lo, hi);
        for (int j = 0; j < 4; ++j) {
          const Vec3 p{lo.x + t(rng) * (hi.x - lo.x), lo.y + t(rng) * (hi.y - lo.y), lo.z + t(rng) * (hi.z - lo.z)};
          const AlphaLevels v = f->levelsAt(p);
          ASSERT_TRUE(lowerInsideUpper(v)) << name << " tree " << k;
          ASSERT_TRUE(levelsWithin(v, b)) << name << " tree " << k;
          necessary += v.lower <= 1.0f;
          partly += v.lower > 0.0f && v.lower < 1.0f;
        }
      }
      if (k % 4 >= 2) continue;  // grids for half the trees
      const EnvelopeGrid grid = EnvelopeGrid::build(*f, 0.08);
      const openvdb::FloatGrid::ConstAccessor upper = upperGrid(grid)->getConstAccessor();
      for (auto it = lowerGrid(grid)->cbeginValueOn(); it; ++it)
        ASSERT_TRUE(lowerInsideUpper({upper.getValue(it.getCoord()), *it})) << name << " tree " << k;
      const std::vector<LevelVolume> v = grid.volumes(alphas);
      for (size_t i = 0; i < v.size(); ++i) {
        EXPECT_LE(v[i].lower_volume, v[i].upper_volume) << name << " " << alphas[i];
        if (i == 0) continue;
        EXPECT_GE(v[i].lower_volume, v[i - 1].lower_volume) << name << " " << alphas[i];
        EXPECT_LE(v[i].upper_volume, v[i - 1].upper_volume) << name << " " << alphas[i];
      }
    }
  }
  // The trees have interiors with graded necessity, and both worlds are drawn: not vacuous.
  EXPECT_GT(necessary, 1000);
  EXPECT_GT(partly, 300);
  EXPECT_GT(membershipTrees, 20);
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
  auto expectChildrenError = [](const std::function<void()>& f) {
    try {
      f();
      ADD_FAILURE() << "bad children accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kInvalidDocument);
      EXPECT_EQ(e.path(), "children");
    }
  };
  expectChildrenError([] { node(CsgOp::kUnion, {"bezier", {}, {}}, {sphere({0, 0, 0}, 1)}); });
  expectChildrenError([] { node(CsgOp::kUnion, {"bezier", {}, {}}, {sphere({0, 0, 0}, 1), nullptr}); });
  expectChildrenError([] { SmoothCsgField(CsgOp::kUnion, NodeOperator({"bezier", {}, {}}), {sphere({0, 0, 0}, 1)}); });
  expectChildrenError([] { MembershipCsgField(CsgOp::kUnion, NodeOperator({"bezier", {}, {}}), {}); });
}

}  // namespace
}  // namespace fsdb
