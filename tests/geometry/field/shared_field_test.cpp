// SharedField (geometry/field/shared_field.h): the same answers as the source it wraps, and a CSG
// DAG whose nodes name the node below twice evaluates each node once per point, box and block,
// 30 levels deep (2^30 leaves expanded), as do its bounding box and its budget count.
#include "geometry/field/shared_field.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>

#include "geometry/field/boundary_method.h"
#include "geometry/field/csg_field.h"
#include "geometry/field/smooth_csg_field.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

// A FuzzyBall that counts the calls made to it.
class CountingBall : public FuzzyBall {
 public:
  CountingBall() : FuzzyBall({0.1, 0.2, -0.1}, 0.8, 1.0, 1.3) {}
  AlphaLevels levelsAt(const Vec3& p) const override {
    ++points;
    return FuzzyBall::levelsAt(p);
  }
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override {
    ++boxes;
    return FuzzyBall::boundsOver(lo, hi);
  }
  void boundingBox(Vec3* lo, Vec3* hi) const override {
    ++boundingBoxes;
    FuzzyBall::boundingBox(lo, hi);
  }
  std::uint64_t budgetExhaustions() const override { return 3; }
  mutable std::atomic<int> points{0}, boxes{0}, boundingBoxes{0};
};

BlockLattice latticeAt(Vec3 origin, double step) {
  BlockLattice b;
  for (int i = 0; i < BlockLattice::kDim; ++i) {
    b.x[i] = origin.x + i * step;
    b.y[i] = origin.y + i * step;
    b.z[i] = origin.z + i * step;
  }
  return b;
}

TEST(SharedField, AnswersAsItsSource) {
  auto ball = std::make_shared<FuzzyBall>(Vec3{0.3, 0, 0}, 0.5, 0.9, 1.4);
  auto other = std::make_shared<FuzzyBall>(Vec3{-0.4, 0.2, 0}, 0.7, 0.8, 1.0);
  auto source = std::make_shared<CsgField>(CsgOp::kDifference, std::vector<std::shared_ptr<const AlphaFieldSource>>{ball, other});
  SharedField shared(source);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    for (int twice = 0; twice < 2; ++twice) {  // the second answer is the remembered one
      const AlphaLevels a = shared.levelsAt(p), b = source->levelsAt(p);
      EXPECT_EQ(a.upper, b.upper);
      EXPECT_EQ(a.lower, b.lower);
    }
    const Vec3 lo = p, hi = p + Vec3{0.3, 0.2, 0.1};
    const AlphaLevelBounds a = shared.boundsOver(lo, hi), b = source->boundsOver(lo, hi);
    EXPECT_EQ(a.upperMin, b.upperMin);
    EXPECT_EQ(a.upperMax, b.upperMax);
    EXPECT_EQ(a.lowerMin, b.lowerMin);
    EXPECT_EQ(a.lowerMax, b.lowerMax);
  }
  for (int i = 0; i < 20; ++i) {
    const BlockLattice b = latticeAt({u(rng), u(rng), u(rng)}, 0.05);
    AlphaLevels got[BlockLattice::kSize], want[BlockLattice::kSize], again[BlockLattice::kSize];
    shared.sampleBlock(b, got);
    shared.sampleBlock(b, again);
    source->sampleBlock(b, want);
    for (int v = 0; v < BlockLattice::kSize; ++v) {
      EXPECT_EQ(got[v].upper, want[v].upper);
      EXPECT_EQ(got[v].lower, want[v].lower);
      EXPECT_EQ(again[v].upper, want[v].upper);
      EXPECT_EQ(again[v].lower, want[v].lower);
    }
  }
  Vec3 lo, hi, slo, shi;
  shared.boundingBox(&lo, &hi);
  source->boundingBox(&slo, &shi);
  EXPECT_EQ(lo.x, slo.x);
  EXPECT_EQ(hi.z, shi.z);
}

// s_0 = the ball; s_k = union(s_{k-1}, s_{k-1}) with s_{k-1} shared: 2^30 leaves expanded.
std::shared_ptr<const AlphaFieldSource> doublingDag(const std::shared_ptr<const AlphaFieldSource>& leaf, int depth) {
  std::shared_ptr<const AlphaFieldSource> node = leaf;
  for (int k = 0; k < depth; ++k) {
    auto shared = std::make_shared<SharedField>(node);
    node = std::make_shared<CsgField>(CsgOp::kUnion, std::vector<std::shared_ptr<const AlphaFieldSource>>{shared, shared});
  }
  return node;
}

TEST(SharedField, ADagThirtyDeepEvaluatesEachNodeOnce) {
  auto leaf = std::make_shared<CountingBall>();
  const auto root = doublingDag(leaf, 30);
  Vec3 lo, hi;
  root->boundingBox(&lo, &hi);
  EXPECT_LE(leaf->boundingBoxes.load(), 2);  // its two parent edges at the lowest level
  EXPECT_DOUBLE_EQ(lo.x, 0.1 - 1.3);
  const Vec3 p{0.5, 0.4, 0.3};
  const AlphaLevels levels = root->levelsAt(p);
  EXPECT_EQ(leaf->points.load(), 1);
  EXPECT_EQ(levels.upper, leaf->FuzzyBall::levelsAt(p).upper);
  root->boundsOver({0, 0, 0}, {0.5, 0.5, 0.5});
  EXPECT_EQ(leaf->boxes.load(), 1);
  AlphaLevels block[BlockLattice::kSize];
  leaf->points = 0;
  leaf->boxes = 0;
  root->sampleBlock(latticeAt({0.6, 0.6, 0.6}, 0.04), block);  // on the ball's boundary: sampled
  EXPECT_LE(leaf->points.load(), BlockLattice::kSize);
  EXPECT_LE(leaf->boxes.load(), 1);
  for (int v = 0; v < BlockLattice::kSize; ++v) {
    const int i = v / 64, j = (v / 8) % 8, k = v % 8;
    EXPECT_EQ(block[v].upper, leaf->FuzzyBall::levelsAt(latticeAt({0.6, 0.6, 0.6}, 0.04).at(i, j, k)).upper);
  }
  // The leaf's count once, not 2^30 times (nor 2^30 calls to find it).
  EXPECT_EQ(root->budgetExhaustions(), 3u);
}

// Smooth nodes (a fuzzy ball stays an alpha source, so the node is a SmoothCsgField) asked their
// children's boxes on every call: 24 levels of such a DAG took 1.3 s for its box, doubling per level.
TEST(SharedField, TheBoundingBoxOfASmoothDagIsFoundOncePerNode) {
  auto leaf = std::make_shared<CountingBall>();
  std::shared_ptr<const AlphaFieldSource> node = leaf;
  for (int k = 0; k < 30; ++k) {
    auto shared = std::make_shared<SharedField>(node);
    node = makeSmoothCsgNode(CsgOp::kUnion, OperatorConfig{"algebraic", {}, {}}, {},
                             std::vector<std::shared_ptr<const AlphaFieldSource>>{shared, shared});
  }
  Vec3 lo, hi;
  node->boundingBox(&lo, &hi);
  EXPECT_LE(leaf->boundingBoxes.load(), 2);
  EXPECT_DOUBLE_EQ(lo.x, 0.1 - 1.3);
  node->boundingBox(&lo, &hi);
  EXPECT_LE(leaf->boundingBoxes.load(), 2);
  const Vec3 p{0.5, 0.4, 0.3};
  node->levelsAt(p);
  EXPECT_EQ(leaf->points.load(), 1);
}

TEST(SharedField, TheBoundarySolidOfADagIsBuiltInTheDagsSize) {
  FuzzyPart part;
  part.a1 = FuzzyNumber::triangular(0.9, 1.0, 1.1);
  auto leaf = std::make_shared<CsgTree>();
  leaf->part = part;
  std::shared_ptr<const CsgTree> node = leaf;
  for (int k = 0; k < 30; ++k) {
    auto parent = std::make_shared<CsgTree>();
    parent->leaf = false;
    parent->op = k % 2 ? CsgOp::kUnion : CsgOp::kIntersection;
    parent->children = {node, node};
    node = parent;
  }
  for (bool upper : {false, true}) {
    const auto solid = boundarySolid(*node, 0.5, upper);
    const auto single = boundarySolid(*leaf, 0.5, upper);
    for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{0.97, 0, 0}, Vec3{1.03, 0, 0}, Vec3{2, 0, 0}}) {
      EXPECT_EQ(solid->levelsAt(p).upper, single->levelsAt(p).upper) << p.x;
      EXPECT_EQ(solid->levelsAt(p).lower, single->levelsAt(p).lower) << p.x;
    }
  }
}

}  // namespace
}  // namespace fsdb
