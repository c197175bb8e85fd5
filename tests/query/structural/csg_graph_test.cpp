// shapeGraph: documents (inline trees, csg text, stored references) as CSG graphs: node kinds,
// paths, flattening of same-operation unions and intersections, shared references as one node
// (a DAG), leaf parts with their transforms, and errors as parseShapeField reports them.
#include "query/structural/csg_graph.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "tests/testing/toy_store.h"

namespace fsdb {
namespace {

using nlohmann::json;
using testing::ToyStore;

json ball(double r) { return {{"kind", "part"}, {"params", {{"a1", r}}}}; }
json leafOf(double r) { return {{"part", ball(r)}}; }
json opOf(const std::string& op, json children) { return {{"op", op}, {"children", std::move(children)}}; }
json shapeOf(json tree) { return {{"kind", "shape"}, {"tree", std::move(tree)}}; }

TEST(CsgGraph, OperationNames) {
  EXPECT_STREQ(csgGraphOpName(CsgGraphOp::Union), "union");
  EXPECT_STREQ(csgGraphOpName(CsgGraphOp::Intersection), "intersection");
  EXPECT_STREQ(csgGraphOpName(CsgGraphOp::Difference), "difference");
  EXPECT_STREQ(csgGraphOpName(CsgGraphOp::Leaf), "leaf");
}

TEST(CsgGraph, InlineTreeWithPathsAndLeafParts) {
  json leafWithTransform = {{"part", ball(2)}, {"transform", {{"translate", {3, 0, 0}}}}};
  const ShapeGraph g = shapeGraph(shapeOf(opOf("difference", {leafOf(1), leafWithTransform})), "shape", 100);
  ASSERT_EQ(g.graph.size(), 3u);
  EXPECT_TRUE(g.graph.isTree());
  EXPECT_EQ(g.graph.root, 0);
  const CsgGraphNode& root = g.graph.nodes[0];
  EXPECT_EQ(root.op, CsgGraphOp::Difference);
  EXPECT_EQ(root.path, "shape.tree");
  ASSERT_EQ(root.children, (std::vector<int>{1, 2}));  // minuend first
  EXPECT_EQ(g.graph.nodes[1].path, "shape.tree.children[0]");
  EXPECT_EQ(g.graph.nodes[2].path, "shape.tree.children[1]");
  EXPECT_EQ(g.graph.leafCount, 2);
  ASSERT_EQ(g.leaves.size(), 2u);
  EXPECT_EQ(g.graph.nodes[2].leaf, 1);
  EXPECT_EQ(g.leaves[1].part.a1.support().lo, 2);
  EXPECT_EQ(g.leaves[1].part.tx.support().lo, 3);  // the leaf transform is on the part
  EXPECT_EQ(g.leaves[0].partId, 0);
  EXPECT_EQ(g.graph.leafPaths(), (std::vector<std::string>{"shape.tree.children[0]", "shape.tree.children[1]"}));
}

TEST(CsgGraph, APartDocumentIsOneLeaf) {
  json part = ball(1);
  part["name"] = "bolt";
  const ShapeGraph g = shapeGraph(part, "doc", 100);
  ASSERT_EQ(g.graph.size(), 1u);
  EXPECT_EQ(g.graph.nodes[0].op, CsgGraphOp::Leaf);
  EXPECT_EQ(g.graph.nodes[0].leaf, 0);
  EXPECT_EQ(g.graph.nodes[0].path, "doc");
  EXPECT_EQ(g.leaves.at(0).name, "bolt");
}

TEST(CsgGraph, NestedSameOperationsFlatten) {
  // (A ∪ (B ∪ C)) ∪ D -> one union of four leaves, each keeping its own path.
  const json tree = opOf("union", {opOf("union", {leafOf(1), opOf("union", {leafOf(2), leafOf(3)})}), leafOf(4)});
  const ShapeGraph g = shapeGraph(shapeOf(tree), "", 100);
  ASSERT_EQ(g.graph.size(), 5u);
  EXPECT_EQ(g.graph.nodes[0].children.size(), 4u);
  EXPECT_EQ(g.graph.nodes[g.graph.nodes[0].children[2]].path, "tree.children[0].children[1].children[1]");
  // Different operations, a difference, and a different operator do not flatten.
  const json mixed = opOf("union", {opOf("intersection", {leafOf(1), leafOf(2)}),
                                    opOf("difference", {opOf("difference", {leafOf(1), leafOf(2)}), leafOf(3)})});
  EXPECT_EQ(shapeGraph(shapeOf(mixed), "", 100).graph.size(), 9u);
  json smooth = opOf("union", {leafOf(1), leafOf(2)});
  smooth["operator"] = {{"name", "algebraic"}};
  EXPECT_EQ(shapeGraph(shapeOf(opOf("union", {smooth, leafOf(3)})), "", 100).graph.size(), 5u);
  json zadeh = opOf("union", {leafOf(1), leafOf(2)});
  zadeh["operator"] = {{"name", "zadeh"}};  // the default written out
  EXPECT_EQ(shapeGraph(shapeOf(opOf("union", {zadeh, leafOf(3)})), "", 100).graph.size(), 4u);
}

TEST(CsgGraph, CsgTextGivesTheSameGraphForAssociativeForms) {
  ToyStore db;
  for (const char* name : {"A", "B", "C"}) db.add("part", name, name[0], {{"kind", "part"}, {"name", name}, {"params", {{"a1", 1}}}});
  const ShapeGraph flat = shapeGraph({{"kind", "shape"}, {"csg", "A + B + C"}}, "", 100, db.resolver());
  const ShapeGraph nested = shapeGraph({{"kind", "shape"}, {"csg", "(A + B) + C"}}, "", 100, db.resolver());
  ASSERT_EQ(flat.graph.size(), 4u);
  ASSERT_EQ(nested.graph.size(), 4u);
  EXPECT_EQ(flat.graph.nodes[0].op, CsgGraphOp::Union);
  EXPECT_EQ(nested.graph.nodes[0].children.size(), 3u);
  EXPECT_EQ(flat.graph.nodes[0].path, "csg");
  EXPECT_EQ(flat.leaves[0].partId, 'A');
  EXPECT_EQ(flat.leaves[2].name, "C");
}

TEST(CsgGraph, SharedReferencesAreOneNodeWithSeveralParents) {
  ToyStore db;
  db.add("shape", "pair", 5, shapeOf(opOf("intersection", {leafOf(1), leafOf(2)})));
  db.add("part", "bolt", 9, {{"kind", "part"}, {"name", "bolt"}, {"params", {{"a1", 1}}}});
  // union(pair, difference(bolt, pair by id)): pair is shared.
  const json tree = opOf("union", {{{"ref", "pair"}}, opOf("difference", {{{"part", "bolt"}}, {{"ref", 5}}})});
  const ShapeGraph g = shapeGraph(shapeOf(tree), "s", 100, db.resolver());
  EXPECT_EQ(db.lookups, 3);  // pair, pair by id, bolt: each once for both passes over the document
  ASSERT_EQ(g.graph.size(), 6u);  // union, pair's intersection + 2 leaves, difference, bolt
  EXPECT_FALSE(g.graph.isTree());
  const std::vector<std::vector<int>> parents = g.graph.parents();
  const int pair = g.graph.nodes[0].children[0];
  EXPECT_EQ(g.graph.nodes[size_t(pair)].op, CsgGraphOp::Intersection);
  EXPECT_EQ(g.graph.nodes[size_t(pair)].path, "s.tree.children[0].ref.tree");
  EXPECT_EQ(parents[size_t(pair)].size(), 2u);
  const int difference = g.graph.nodes[0].children[1];
  EXPECT_EQ(g.graph.nodes[size_t(difference)].children[1], pair);
  EXPECT_EQ(g.graph.leafCount, 3);
  const int bolt = g.graph.nodes[size_t(difference)].children[0];
  EXPECT_EQ(g.leaves[size_t(g.graph.nodes[size_t(bolt)].leaf)].partId, 9);
  EXPECT_EQ(g.leaves[size_t(g.graph.nodes[size_t(bolt)].leaf)].name, "bolt");
}

TEST(CsgGraph, ASharedUnionIsNotFlattenedButASingleUseReferenceIs) {
  ToyStore db;
  db.add("shape", "u", 3, shapeOf(opOf("union", {leafOf(1), leafOf(2)})));
  const ShapeGraph once = shapeGraph(shapeOf(opOf("union", {{{"ref", "u"}}, leafOf(3)})), "", 100, db.resolver());
  EXPECT_EQ(once.graph.size(), 4u);  // one union of three leaves
  EXPECT_TRUE(once.graph.isTree());
  const ShapeGraph twice =
      shapeGraph(shapeOf(opOf("union", {{{"ref", "u"}}, {{"ref", "u"}}})), "", 100, db.resolver());
  EXPECT_EQ(twice.graph.size(), 4u);  // the root and the shared union with its two leaves
  EXPECT_EQ(twice.graph.nodes[0].children, (std::vector<int>{1, 1}));  // both edges kept
  EXPECT_FALSE(twice.graph.isTree());
}

TEST(CsgGraph, ErrorsAreThoseOfParseShapeField) {
  ToyStore db;
  try {
    shapeGraph(shapeOf(opOf("union", {leafOf(1), {{"ref", "nope"}}})), "s", 100, db.resolver());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kUnknownReference);
    EXPECT_EQ(e.path(), "s.tree.children[1].ref");
  }
  try {
    shapeGraph(shapeOf(opOf("union", {leafOf(1), leafOf(2)})), "", 2);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kLimitExceeded);
  }
}

TEST(CsgGraph, IsTreeAndParentsOnHandMadeGraphs) {
  CsgGraph g;
  g.nodes.resize(3);
  g.nodes[0].op = CsgGraphOp::Union;
  g.nodes[0].children = {1, 2};
  g.nodes[1].leaf = 0;
  g.nodes[2].leaf = 1;
  g.leafCount = 2;
  EXPECT_TRUE(g.isTree());
  EXPECT_EQ(g.parents()[2], (std::vector<int>{0}));
  g.nodes[0].children = {1, 1};
  EXPECT_FALSE(g.isTree());
}

}  // namespace
}  // namespace fsdb
