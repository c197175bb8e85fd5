// query/shape_json: CSG shape documents to one alpha field, with counts, limits and paths.
#include "query/shape_json.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

json ball(double r, double x) {
  return {{"part", {{"params", {{"a1", r}}}}}, {"transform", {{"translate", {x, 0, 0}}}}};
}

Error errorOf(const json& doc, size_t maxNodes = 100) {
  try {
    parseShapeField(doc, "shape", maxNodes);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << doc.dump();
  return Error("", "");
}

TEST(ShapeJson, BuildsTheFieldOfANestedTree) {
  json doc = {{"kind", "shape"},
              {"tree", {{"op", "union"},
                        {"operator", {{"name", "zadeh"}}},
                        {"children", {ball(1, 0), {{"op", "difference"}, {"children", {ball(1, 3), ball(0.5, 3.5)}}}}}}}};
  ParsedShape s = parseShapeField(doc, "shape", 100);
  EXPECT_EQ(s.nodeCount, 5u);
  EXPECT_EQ(s.partCount, 3u);
  EXPECT_EQ(s.field->levelsAt({0, 0, 0}).upper, 1.0f);    // inside the first ball
  EXPECT_EQ(s.field->levelsAt({3.5, 0, 0}).upper, 0.0f);  // cut away by the difference
  EXPECT_EQ(s.field->levelsAt({2.3, 0, 0}).lower, 0.0f);  // left of the cut
}

TEST(ShapeJson, AcceptsAPartDocumentAsAOneLeafTree) {
  ParsedShape s = parseShapeField(json{{"kind", "part"}, {"params", {{"a1", 2}}}}, "shape", 1);
  EXPECT_EQ(s.nodeCount, 1u);
  EXPECT_EQ(s.field->levelsAt({1.9, 0, 0}).lower, 0.0f);
}

TEST(ShapeJson, ErrorsNameTheJsonPath) {
  json leafWithTwoTransforms = ball(1, 0);
  leafWithTwoTransforms["part"]["transform"] = {{"scale", 2}};
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), leafWithTwoTransforms}}}}}).path(),
            "shape.tree.children[1].transform");
  json badLeafTransform = ball(1, 0);
  badLeafTransform["transform"] = {{"scale", -2}};
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), badLeafTransform}}}}}).path(),
            "shape.tree.children[1].transform.scale");
  EXPECT_EQ(errorOf({{"tree", {{"op", "xor"}, {"children", {ball(1, 0), ball(1, 1)}}}}}).path(), "shape.tree.op");
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0)}}}}}).path(), "shape.tree.children");
  EXPECT_EQ(errorOf({{"tree", {{"ref", "lamp"}}}}).path(), "shape.tree.ref");
  EXPECT_EQ(errorOf({{"csg", "C = A + B"}}).path(), "shape.csg");
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"operator", {{"name", "dombi"}}}, {"children", {ball(1, 0), ball(1, 1)}}}}})
                .path(),
            "shape.tree.operator.name");
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"operator", {{"name", "nope"}}}, {"children", {ball(1, 0), ball(1, 1)}}}}})
                .code(),
            errc::kUnknownName);
  Error limit = errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), ball(1, 1)}}}}}, 2);
  EXPECT_EQ(limit.code(), errc::kLimitExceeded);
  EXPECT_EQ(errorOf({{"kind", "curve"}}).path(), "shape.kind");
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), ball(1, 1)}}, {"extra", 1}}}}).path(),
            "shape.tree.extra");
}

}  // namespace
}  // namespace fsdb
