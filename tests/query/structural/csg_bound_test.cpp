// The score bounds of query/structural/csg_bound.h: never below the score of the best mapping
// (largestCommonSubgraph + scoreCommonSubgraph) on random trees and DAGs, the matrix bound never
// above the signature bound, and tight for an exact match.
#include "query/structural/csg_bound.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/testing/random_csg_graph.h"

namespace fsdb {
namespace {

TEST(CsgBound, SignatureCountsNodesByOperation) {
  std::mt19937 rng(3);
  const CsgGraph g = testing::randomTree(rng, 9);
  const CsgSignature s = csgSignature(g);
  EXPECT_EQ(s.nodes(), int(g.size()));
  EXPECT_EQ(s.leaves, g.leafCount);
}

TEST(CsgBound, BoundsNeverUnderestimateTheScore) {
  std::mt19937 rng(20261201);
  const CsgWeights weightSets[] = {{}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.3, 0.5}};
  for (int trial = 0; trial < 400; ++trial) {
    const bool dag = trial % 4 == 3;
    const int qn = std::uniform_int_distribution<int>(1, 9)(rng), sn = std::uniform_int_distribution<int>(1, 12)(rng);
    const CsgGraph q = dag ? testing::randomDag(rng, qn, 2) : testing::randomTree(rng, qn);
    const CsgGraph s = dag ? testing::randomDag(rng, sn, 2) : testing::randomTree(rng, sn);
    const LeafSimilarityMatrix leaf = testing::randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    const LeafSimilarityMatrix transform = testing::randomLeafSimilarity(rng, q.leafCount, s.leafCount);
    const double leafThreshold = trial % 3 == 0 ? 0.4 : 0.0;
    const CommonSubgraph m = largestCommonSubgraph(q, s, leaf, {leafThreshold, 1000});
    for (const CsgWeights& w : weightSets) {
      const double score = scoreCommonSubgraph(q, s, m, transform, w).score;
      const double sig = signatureBound(csgSignature(q), csgSignature(s), w);
      const double mat = matrixBound(csgSignature(q), csgSignature(s), leaf, transform, leafThreshold, w);
      EXPECT_GE(mat, score) << "trial " << trial;
      EXPECT_GE(sig, mat - 1e-12) << "trial " << trial;
    }
  }
}

TEST(CsgBound, ExactMatchBoundIsOne) {
  std::mt19937 rng(5);
  const CsgGraph g = testing::randomTree(rng, 7);
  LeafSimilarityMatrix ones{g.leafCount, g.leafCount, std::vector<double>(size_t(g.leafCount * g.leafCount), 1.0)};
  EXPECT_NEAR(signatureBound(csgSignature(g), csgSignature(g), {}), 1.0, 1e-6);
  EXPECT_NEAR(matrixBound(csgSignature(g), csgSignature(g), ones, ones, 0, {}), 1.0, 1e-6);
  // A stored graph with twice the leaves and no operation in common bounds well below 1.
  CsgSignature big = csgSignature(g);
  big.leaves *= 2;
  big.unions = big.intersections = big.differences = 0;
  EXPECT_LT(signatureBound(csgSignature(g), big, {}), 0.9);
}

}  // namespace
}  // namespace fsdb
