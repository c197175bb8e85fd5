// query/document/shape_json with a ReferenceResolver: stored parts and shapes by name or id, shared
// subtrees built once, cycles, unknown references, the csg text form, and outlineTree.
#include <gtest/gtest.h>

#include <map>

#include "geometry/core/error.h"
#include "query/document/shape_json.h"
#include "tests/testing/toy_store.h"

namespace fsdb {
namespace {

using nlohmann::json;
using testing::ToyStore;

json ballPart(double r, double x) {
  return {{"kind", "part"}, {"params", {{"a1", r}}}, {"transform", {{"translate", {x, 0, 0}}}}};
}

Error errorOf(const json& doc, const ReferenceResolver& resolver) {
  try {
    parseShapeField(doc, "", 100, resolver);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << doc.dump();
  return Error("", "");
}

TEST(ShapeRefs, ResolvesPartsByNameAndIdWithALeafTransform) {
  ToyStore db;
  db.add("part", "ball", 1, {{"kind", "part"}, {"name", "ball"}, {"params", {{"a1", 1}}}});
  json doc = {{"kind", "shape"},
              {"tree",
               {{"op", "union"},
                {"children", {{{"part", "ball"}}, {{"part", 1}, {"transform", {{"translate", {3, 0, 0}}}}}}}}}};
  ParsedShape s = parseShapeField(doc, "", 100, db.resolver());
  EXPECT_EQ(s.partCount, 2u);
  EXPECT_EQ(s.field->levelsAt({0, 0, 0}).upper, 1.0f);
  EXPECT_EQ(s.field->levelsAt({3, 0, 0}).upper, 1.0f);
  EXPECT_EQ(s.field->levelsAt({1.5, 0, 0}).upper, 0.0f);
}

TEST(ShapeRefs, ASharedShapeIsBuiltOnceAndCountedOnce) {
  ToyStore db;
  db.add("shape", "pair", 5,
         {{"kind", "shape"}, {"tree", {{"op", "union"}, {"children", {{{"part", ballPart(1, 0)}}, {{"part", ballPart(1, 3)}}}}}}});
  json doc = {{"tree", {{"op", "intersection"}, {"children", {{{"ref", "pair"}}, {{"ref", 5}}}}}}};
  ParsedShape s = parseShapeField(doc, "", 100, db.resolver());
  EXPECT_EQ(s.nodeCount, 6u);  // intersection, its two ref leaves, and the stored union + 2 leaves once
  EXPECT_EQ(s.partCount, 2u);
  ASSERT_EQ(s.tree->children.size(), 2u);
  EXPECT_EQ(s.tree->children[0], s.tree->children[1]);  // the same subtree object
  EXPECT_EQ(s.field->levelsAt({3, 0, 0}).upper, 1.0f);
}

TEST(ShapeRefs, UnknownReferencesAndCyclesNameTheirPath) {
  ToyStore db;
  db.add("shape", "loop", 7, {{"kind", "shape"}, {"tree", {{"op", "union"}, {"children", {{{"part", ballPart(1, 0)}}, {{"ref", "loop"}}}}}}});
  Error unknown = errorOf({{"tree", {{"op", "union"}, {"children", {{{"part", "nope"}}, {{"part", ballPart(1, 0)}}}}}}},
                          db.resolver());
  EXPECT_EQ(unknown.code(), errc::kUnknownReference);
  EXPECT_EQ(unknown.path(), "tree.children[0].part");
  EXPECT_STREQ(unknown.what(), "unknown part 'nope'");
  Error cycle = errorOf({{"tree", {{"ref", "loop"}}}}, db.resolver());
  EXPECT_EQ(cycle.code(), errc::kReferenceCycle);
  EXPECT_EQ(cycle.path(), "tree.ref.tree.children[1].ref");
  EXPECT_EQ(errorOf({{"tree", {{"ref", ""}}}}, db.resolver()).path(), "tree.ref");
  EXPECT_EQ(errorOf({{"tree", {{"ref", -3}}}}, db.resolver()).code(), errc::kInvalidDocument);
  Error placed = errorOf({{"tree", {{"ref", "loop"}, {"transform", {{"scale", 2}}}}}}, db.resolver());
  EXPECT_EQ(placed.path(), "tree.transform");
}

TEST(ShapeRefs, TheCsgTextFormResolvesNamesToPartsThenShapes) {
  ToyStore db;
  db.add("part", "A", 1, ballPart(1, 0));
  db.add("part", "B", 2, ballPart(1, 1.5));
  db.add("shape", "S", 3, {{"kind", "shape"}, {"csg", "A + B"}});
  ParsedShape s = parseShapeField({{"kind", "shape"}, {"name", "C"}, {"csg", "C = S - B"}}, "", 100, db.resolver());
  EXPECT_EQ(s.field->levelsAt({0, 0, 0}).upper, 1.0f);   // A, not cut
  EXPECT_EQ(s.field->levelsAt({1.5, 0, 0}).upper, 0.0f);  // B removed
  Error wrongName = errorOf({{"name", "D"}, {"csg", "C = A + B"}}, db.resolver());
  EXPECT_EQ(wrongName.path(), "csg");
  Error unknown = errorOf({{"csg", "A + Z"}}, db.resolver());
  EXPECT_EQ(unknown.code(), errc::kUnknownReference);
  EXPECT_STREQ(unknown.what(), "csg: 'Z' at column 5 is no stored part or shape");
  EXPECT_EQ(errorOf({{"csg", "A + B"}, {"tree", {{"part", "A"}}}}, db.resolver()).path(), "csg");
}

TEST(ShapeRefs, TheParsedShapeKeepsTheResolvedTreeAndEachReferenceIsLookedUpOnce) {
  ToyStore db;
  db.add("part", "A", 1, ballPart(1, 0));
  db.add("part", "B", 2, ballPart(1, 1.5));
  const json doc = {{"kind", "shape"}, {"csg", "A + B - A"}};
  const json expected = shapeTree(doc, "shape", db.resolver());
  db.lookups = 0;
  ParsedShape s = parseShapeField(doc, "shape", 100, db.resolver());
  EXPECT_EQ(s.documentTree, expected);
  EXPECT_EQ(s.documentTreePath, "shape.csg");
  EXPECT_EQ(db.lookups, 2);  // part A, part B: the text and the walk share the answers
  ParsedShape t = parseShapeField({{"kind", "shape"}, {"tree", expected}}, "", 100, db.resolver());
  EXPECT_EQ(t.documentTree, expected);
  EXPECT_EQ(t.documentTreePath, "tree");
}

TEST(ShapeRefs, WithoutAResolverReferencesAreRefusedWithTheirPath) {
  Error e = errorOf({{"tree", {{"op", "union"}, {"children", {{{"part", "x"}}, {{"part", "y"}}}}}}}, {});
  EXPECT_EQ(e.code(), errc::kInvalidDocument);
  EXPECT_EQ(e.path(), "tree.children[0].part");
}

TEST(ShapeRefs, OutlineListsNodesInPreorderWithReferences) {
  json tree = {{"op", "difference"},
               {"operator", {{"name", "zadeh"}}},
               {"children",
                {{{"part", "bolt"}, {"transform", {{"scale", 2}}}},
                 {{"op", "union"}, {"children", {{{"ref", 12}}, {{"part", ballPart(1, 0)}}}}}}}};
  TreeOutline o = outlineTree(tree, "tree");
  ASSERT_EQ(o.nodes.size(), 5u);
  EXPECT_EQ(o.nodes[0].kind, "difference");
  EXPECT_EQ(o.nodes[0].operatorDoc, json({{"name", "zadeh"}}));
  EXPECT_EQ(o.nodes[1].kind, "ref");
  EXPECT_EQ(o.nodes[1].parent, 0);
  EXPECT_EQ(o.nodes[1].transform, json({{"scale", 2}}));
  EXPECT_EQ(o.nodes[2].kind, "union");
  EXPECT_EQ(o.nodes[2].position, 1);
  EXPECT_EQ(o.nodes[3].kind, "ref");
  EXPECT_EQ(o.nodes[3].parent, 2);
  EXPECT_EQ(o.nodes[4].kind, "part");
  ASSERT_EQ(o.references.size(), 2u);
  EXPECT_EQ(o.references[0].kind, "part");
  EXPECT_EQ(o.references[0].key, "bolt");
  EXPECT_EQ(o.references[0].path, "tree.children[0].part");
  EXPECT_EQ(o.references[1].kind, "shape");
  EXPECT_EQ(o.references[1].key, 12);
  EXPECT_EQ(o.references[1].path, "tree.children[1].children[0].ref");
}

TEST(ShapeRefs, RememberingResolverAsksOncePerReference) {
  ToyStore db;
  db.add("part", "ball", 1, ballPart(1, 0));
  const ReferenceResolver r = rememberingResolver(db.resolver());
  EXPECT_EQ(r("part", "ball")->id, 1);
  EXPECT_EQ(r("part", "ball")->id, 1);
  EXPECT_FALSE(r("part", "nope").has_value());
  EXPECT_FALSE(r("part", "nope").has_value());
  EXPECT_EQ(db.lookups, 2);
  EXPECT_FALSE(rememberingResolver({}));  // no resolver stays none
}

}  // namespace
}  // namespace fsdb
