// CSG scores (query/structural/csg_similarity.h): exact match 1, swapped union children 1, swapped difference
// children below 1, the weights as documented; partSimilarity and transformSimilarity.
#include "query/structural/csg_similarity.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/structural/csg_graph.h"
#include "tests/testing/random_csg_graph.h"

namespace fsdb {
namespace {

CsgGraph twoLeaves(CsgGraphOp op) {
  CsgGraph g;
  g.nodes.resize(3);
  g.nodes[0].op = op;
  g.nodes[0].children = {1, 2};
  g.nodes[1].leaf = 0;
  g.nodes[2].leaf = 1;
  g.leafCount = 2;
  return g;
}

LeafSimilarityMatrix matrix(std::vector<double> v) { return {2, 2, std::move(v)}; }
const LeafSimilarityMatrix kIdentity = matrix({1, 0, 0, 1});
const LeafSimilarityMatrix kSwapped = matrix({0, 1, 1, 0});

CsgScore scoreOf(const CsgGraph& q, const CsgGraph& s, const LeafSimilarityMatrix& leaves,
                 const LeafSimilarityMatrix& transforms, const CsgWeights& w = {}) {
  return scoreCommonSubgraph(q, s, largestCommonSubgraph(q, s, leaves), transforms, w);
}

TEST(CsgSimilarity, AnExactTreeScoresOne) {
  const CsgGraph g = twoLeaves(CsgGraphOp::Difference);
  const CsgScore s = scoreOf(g, g, kIdentity, kIdentity);
  EXPECT_DOUBLE_EQ(s.score, 1);
  EXPECT_DOUBLE_EQ(s.structure, 1);
  EXPECT_DOUBLE_EQ(s.components, 1);
  EXPECT_DOUBLE_EQ(s.transforms, 1);
}

TEST(CsgSimilarity, SwappedUnionChildrenScoreOne) {
  const CsgGraph g = twoLeaves(CsgGraphOp::Union);
  EXPECT_DOUBLE_EQ(scoreOf(g, g, kSwapped, kSwapped).score, 1);
}

TEST(CsgSimilarity, SwappedDifferenceChildrenScoreBelowOne) {
  const CsgGraph g = twoLeaves(CsgGraphOp::Difference);
  const CsgScore s = scoreOf(g, g, kSwapped, kSwapped);
  EXPECT_LT(s.score, 1);
  EXPECT_LT(s.structure, 1);
}

TEST(CsgSimilarity, TermsAndWeightsAsDocumented) {
  // Union of two leaves against a union of three: both query leaves matched with 0.8 and 0.6,
  // transforms 0.5 and 1.
  CsgGraph q = twoLeaves(CsgGraphOp::Union), s = twoLeaves(CsgGraphOp::Union);
  s.nodes[0].children.push_back(3);
  s.nodes.emplace_back();
  s.nodes[3].leaf = 2;
  s.leafCount = 3;
  const LeafSimilarityMatrix leaves{2, 3, {0.8, 0, 0, 0, 0.6, 0}};
  const LeafSimilarityMatrix transforms{2, 3, {0.5, 0, 0, 0, 1, 0}};
  const CommonSubgraph m = largestCommonSubgraph(q, s, leaves);
  ASSERT_EQ(m.matchedNodes, 3);
  const CsgScore d = scoreCommonSubgraph(q, s, m, transforms, {});
  EXPECT_NEAR(d.structure, 3.0 / 4, 1e-12);
  EXPECT_NEAR(d.components, 1.4 / 3, 1e-12);
  EXPECT_NEAR(d.transforms, 1.5 / 3, 1e-12);
  EXPECT_NEAR(d.score, 0.5 * 1.4 / 3 + 0.2 * 1.5 / 3 + 0.3 * 0.75, 1e-12);
  // Only structure counts: the score is the structure term; scaling all weights changes nothing.
  EXPECT_NEAR(scoreCommonSubgraph(q, s, m, transforms, {0, 0, 1}).score, 0.75, 1e-12);
  EXPECT_NEAR(scoreCommonSubgraph(q, s, m, transforms, {5, 2, 3}).score, d.score, 1e-12);
  EXPECT_NEAR(scoreCommonSubgraph(q, s, m, transforms, {1, 0, 0}).score, 1.4 / 3, 1e-12);
}

// Score 1 exactly when everything matches perfectly, on random pairs and on random self matches.
TEST(CsgSimilarity, ScoreOneOnlyForAnExactMatch) {
  std::mt19937 rng(6101);
  for (int trial = 0; trial < 2000; ++trial) {
    const CsgGraph q = testing::randomTree(rng, std::uniform_int_distribution<int>(1, 9)(rng));
    const bool self = trial % 3 == 0;
    const CsgGraph s = self ? q : testing::randomTree(rng, std::uniform_int_distribution<int>(1, 9)(rng));
    LeafSimilarityMatrix leaves = testing::randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    LeafSimilarityMatrix transforms = testing::randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    if (self)
      for (int i = 0; i < q.leafCount; ++i)
        for (int j = 0; j < q.leafCount; ++j) {
          leaves.values[size_t(i) * q.leafCount + j] = i == j ? 1 : 0;
          transforms.values[size_t(i) * q.leafCount + j] = i == j || trial % 2 ? 1 : 0;
        }
    const CommonSubgraph m = largestCommonSubgraph(q, s, leaves);
    const CsgScore c = scoreCommonSubgraph(q, s, m, transforms, {});
    EXPECT_GE(c.score, 0);
    EXPECT_LE(c.score, 1);
    bool perfect = m.matchedNodes == int(q.size()) && q.size() == s.size();
    for (const NodeMatch& x : m.matches)
      if (q.nodes[size_t(x.queryNode)].op == CsgGraphOp::Leaf) {
        perfect = perfect && x.similarity == 1 &&
                  transforms.at(q.nodes[size_t(x.queryNode)].leaf, s.nodes[size_t(x.storedNode)].leaf) == 1;
      }
    EXPECT_EQ(c.score == 1, perfect) << "trial " << trial;
    if (self) {
      EXPECT_EQ(c.score, 1);
    }
  }
}

TEST(CsgSimilarity, RejectsBadWeightsAndMatrices) {
  const CsgGraph g = twoLeaves(CsgGraphOp::Union);
  const CommonSubgraph m = largestCommonSubgraph(g, g, kIdentity);
  EXPECT_THROW(scoreCommonSubgraph(g, g, m, kIdentity, {0, 0, 0}), Error);
  EXPECT_THROW(scoreCommonSubgraph(g, g, m, kIdentity, {-1, 1, 1}), Error);
  EXPECT_THROW(scoreCommonSubgraph(g, g, m, LeafSimilarityMatrix{1, 1, {1}}, {}), Error);
}

TEST(CsgSimilarity, PartSimilarityIsTheMinimumOverShapeParameters) {
  FuzzyPart a, b;
  EXPECT_DOUBLE_EQ(partSimilarity(a, b), 1);
  a.eps1 = FuzzyNumber::triangular(0.5, 1, 1.5);
  b.eps1 = FuzzyNumber::triangular(0.5, 1, 1.5);
  a.kv = FuzzyNumber::triangular(0, 0.1, 0.2);
  b.kv = FuzzyNumber::triangular(0.1, 0.2, 0.3);
  EXPECT_DOUBLE_EQ(partSimilarity(a, b), similarity(a.kv, b.kv));
  b.tx = FuzzyNumber::crisp(5);  // placement is not part of it
  EXPECT_DOUBLE_EQ(partSimilarity(a, b), similarity(a.kv, b.kv));
  b.a1 = FuzzyNumber::crisp(9);
  EXPECT_DOUBLE_EQ(partSimilarity(a, b), 0);
}

TEST(CsgSimilarity, TransformSimilarity) {
  FuzzyPart a, b;
  EXPECT_DOUBLE_EQ(transformSimilarity(a, b), 1);
  a.tx = FuzzyNumber::triangular(0, 1, 2);
  b.tx = FuzzyNumber::triangular(0.5, 1.5, 2.5);
  const double sx = similarity(a.tx, b.tx);
  EXPECT_DOUBLE_EQ(transformSimilarity(a, b), sx);
  // Rotations: the same rotation written with the opposite axis and angle is the same.
  a.tx = b.tx = FuzzyNumber::crisp(0);
  a.deg = FuzzyNumber::triangular(20, 30, 40);
  a.axis = {0, 0, 1};
  b.deg = FuzzyNumber::triangular(-40, -30, -20);
  b.axis = {0, 0, -1};
  EXPECT_NEAR(transformSimilarity(a, b), 1, 1e-12);
  // Perpendicular axes: nothing in common; the identity's axis does not matter.
  b.deg = a.deg;
  b.axis = {1, 0, 0};
  EXPECT_DOUBLE_EQ(transformSimilarity(a, b), 0);
  FuzzyPart identityX, identityZ;
  identityX.axis = {1, 0, 0};
  EXPECT_DOUBLE_EQ(transformSimilarity(identityX, identityZ), 1);
  b.scale = FuzzyNumber::crisp(2);
  b.deg = FuzzyNumber::crisp(0);
  EXPECT_DOUBLE_EQ(transformSimilarity(identityZ, b), 0);
}

}  // namespace
}  // namespace fsdb
