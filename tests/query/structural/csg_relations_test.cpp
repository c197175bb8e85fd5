// Spatial relations of CSG query texts scored on a mapping (query/structural/csg_relations.h): the
// membership of the stored placement, 0 for an unmatched reference, and the move to an equal
// sibling that the words describe.
#include "query/structural/csg_relations.h"

#include <gtest/gtest.h>

#include "query/linguistic/descriptors.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_similarity.h"

namespace fsdb {
namespace {

CsgQuery query(const std::string& text) { return parseCsgQuery(text, Vocabulary::builtin(), {}, 1000); }

// {"part":{"kind":"part","text":words},"transform":{"translate":at}}
nlohmann::json placed(const std::string& words, std::vector<double> at) {
  return {{"part", {{"kind", "part"}, {"text", words}}}, {"transform", {{"translate", at}}}};
}

ShapeGraph stored(nlohmann::json children) {
  return shapeGraph({{"kind", "shape"}, {"name", "s"}, {"tree", {{"op", "union"}, {"children", std::move(children)}}}},
                    "", 1000);
}

struct Scored {
  std::vector<RelationScore> relations;
  CommonSubgraph match;
  CsgScore score;
};

// As the CSG search scores a stored shape: descriptions against the stored leaves' descriptors,
// transform similarity 1 for descriptions, then the relations.
Scored score(const CsgQuery& q, const ShapeGraph& s) {
  const int rows = q.graph.leafCount, cols = s.graph.leafCount;
  LeafSimilarityMatrix leaf{rows, cols, std::vector<double>(size_t(rows * cols))};
  LeafSimilarityMatrix transform{rows, cols, std::vector<double>(size_t(rows * cols), 1.0)};
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      leaf.values[size_t(i * cols + j)] =
          scoreDescriptors(*q.leaves[size_t(i)].condition, describePart(s.leaves[size_t(j)].part)).score;
  Scored out;
  out.match = largestCommonSubgraph(q.graph, s.graph, leaf);
  out.relations = scoreRelations(q, s, leaf, out.match, transform);
  out.score = scoreCommonSubgraph(q.graph, s.graph, out.match, transform, {});
  return out;
}

TEST(CsgRelations, TheMembershipOfTheStoredPlacement) {
  const CsgQuery q = query("a sphere on top of a cylinder");
  ASSERT_TRUE(hasRelations(q));
  EXPECT_FALSE(hasRelations(query("a sphere and a cylinder")));
  const Scored onTop = score(q, stored({placed("a cylinder", {0, 0, 0}), placed("a sphere", {0, 3, 0})}));
  const Scored beside = score(q, stored({placed("a cylinder", {0, 0, 0}), placed("a sphere", {3, 0, 0})}));
  ASSERT_EQ(onTop.relations.size(), 1u);
  EXPECT_DOUBLE_EQ(onTop.relations[0].score, 1.0);
  EXPECT_EQ(onTop.relations[0].storedLeaf, 1);
  EXPECT_EQ(onTop.relations[0].storedReference, 0);
  EXPECT_DOUBLE_EQ(beside.relations[0].score, 0.0);
  // Same structure and components: the relation alone orders them, through the transform term.
  EXPECT_DOUBLE_EQ(onTop.score.components, beside.score.components);
  EXPECT_GT(onTop.score.transforms, beside.score.transforms);
  EXPECT_GT(onTop.score.score, beside.score.score);
  // Half-way up (45° from the top): the trapezoid's slope, strictly between.
  const Scored diagonal = score(q, stored({placed("a cylinder", {0, 0, 0}), placed("a sphere", {2, 2.5, 0})}));
  EXPECT_GT(diagonal.relations[0].score, 0.0);
  EXPECT_LT(diagonal.relations[0].score, 1.0);
}

TEST(CsgRelations, DistancesAreFuzzyNumbers) {
  const CsgQuery q = query("a cube and a sphere about 2 units to its right");
  const Scored at2 = score(q, stored({placed("a cube", {0, 0, 0}), placed("a sphere", {2, 0, 0})}));
  const Scored at21 = score(q, stored({placed("a cube", {0, 0, 0}), placed("a sphere", {2.1, 0, 0})}));
  const Scored at4 = score(q, stored({placed("a cube", {0, 0, 0}), placed("a sphere", {4, 0, 0})}));
  const Scored left = score(q, stored({placed("a cube", {0, 0, 0}), placed("a sphere", {-2, 0, 0})}));
  EXPECT_DOUBLE_EQ(at2.relations[0].score, 1.0);
  EXPECT_NEAR(at21.relations[0].score, 0.5, 1e-9);  // tri(1.8, 2, 2.2) at 2.1
  EXPECT_DOUBLE_EQ(at4.relations[0].score, 0.0);
  EXPECT_DOUBLE_EQ(left.relations[0].score, 0.0);
}

TEST(CsgRelations, AnUnmatchedReferenceChecksNothing) {
  // An untwisted cylinder is no very twisted box at all (similarity 0): the sphere matches, its
  // reference cannot.
  const CsgQuery q = query("a sphere on top of a very twisted box");
  const Scored s = score(q, stored({placed("a sphere", {0, 3, 0}), placed("a cylinder", {0, 0, 0})}));
  ASSERT_EQ(s.relations.size(), 1u);
  EXPECT_EQ(s.relations[0].storedReference, -1);
  EXPECT_FALSE(s.relations[0].checked);
  // The sphere keeps the transform similarity of a description (1); the missing box costs in
  // components and structure.
  EXPECT_DOUBLE_EQ(s.relations[0].score, 1.0);
  EXPECT_DOUBLE_EQ(s.score.transforms, 0.5);  // 1 over max(2, 2) leaves
  EXPECT_LT(s.score.components, 1.0);
}

TEST(CsgRelations, AnEqualSiblingThatTheWordsDescribeIsPreferred) {
  // Two equal spheres, beside and on top: the common subgraph cannot tell them apart; the relation can.
  const CsgQuery q = query("a sphere on top of a cylinder");
  for (const bool topFirst : {false, true}) {
    // json::array, not = {...}: clang takes a one-element brace list as a copy of the object.
    nlohmann::json children = nlohmann::json::array({placed("a cylinder", {0, 0, 0})});
    children.push_back(placed("a sphere", topFirst ? std::vector<double>{0, 3, 0} : std::vector<double>{3, 0, 0}));
    children.push_back(placed("a sphere", topFirst ? std::vector<double>{3, 0, 0} : std::vector<double>{0, 3, 0}));
    const ShapeGraph s = stored(children);
    const Scored got = score(q, s);
    EXPECT_DOUBLE_EQ(got.relations[0].score, 1.0) << topFirst;
    EXPECT_EQ(got.relations[0].storedLeaf, topFirst ? 1 : 2) << topFirst;
    // The mapping moved consistently: the sphere's node is the top one, the weight unchanged.
    double weight = 0;
    for (const NodeMatch& m : got.match.matches) weight += m.similarity;
    EXPECT_NEAR(got.match.weight, weight, 1e-12);
    bool found = false;
    for (const NodeMatch& m : got.match.matches)
      if (s.graph.nodes[size_t(m.storedNode)].op == CsgGraphOp::Leaf &&
          s.graph.nodes[size_t(m.storedNode)].leaf == got.relations[0].storedLeaf)
        found = true;
    EXPECT_TRUE(found);
  }
}

TEST(CsgRelations, ChainsScoreEachLink) {
  const CsgQuery q = query("a cone on top of a cylinder on top of a box");
  const Scored stacked =
      score(q, stored({placed("a box", {0, 0, 0}), placed("a cylinder", {0, 3, 0}), placed("a cone", {0, 6, 0})}));
  ASSERT_EQ(stacked.relations.size(), 2u);
  EXPECT_DOUBLE_EQ(stacked.relations[0].score, 1.0);
  EXPECT_DOUBLE_EQ(stacked.relations[1].score, 1.0);
  const Scored row =
      score(q, stored({placed("a box", {0, 0, 0}), placed("a cylinder", {0, 3, 0}), placed("a cone", {3, 3, 0})}));
  EXPECT_LT(row.score.score, stacked.score.score);
}

}  // namespace
}  // namespace fsdb
