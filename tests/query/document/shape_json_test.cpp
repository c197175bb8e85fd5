// query/document/shape_json: CSG shape documents to one alpha field, with counts, limits and paths.
#include "query/document/shape_json.h"

#include <gtest/gtest.h>

#include "geometry/voxel/envelope_grid.h"
#include "geometry/core/error.h"
#include "geometry/field/smooth_csg_field.h"

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
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"operator", {{"name", "nope"}}}, {"children", {ball(1, 0), ball(1, 1)}}}}})
                .code(),
            errc::kUnknownName);
  Error limit = errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), ball(1, 1)}}}}}, 2);
  EXPECT_EQ(limit.code(), errc::kLimitExceeded);
  EXPECT_EQ(errorOf({{"kind", "curve"}}).path(), "shape.kind");
  EXPECT_EQ(errorOf({{"tree", {{"op", "union"}, {"children", {ball(1, 0), ball(1, 1)}}, {"extra", 1}}}}).path(),
            "shape.tree.extra");
}

json smoothUnion(json op, json children) {
  return {{"tree", {{"op", "union"}, {"operator", std::move(op)}, {"children", std::move(children)}}}};
}

TEST(ShapeJson, SmoothOperatorsAreAcceptedWithTheirParameters) {
  json doc = smoothUnion({{"name", "bezier"}, {"n", 3}}, {ball(1, 0), ball(1, 1.9)});
  doc["tree"]["range"] = 0.2;
  doc["tree"]["step"] = {{"name", "bspline"}, {"m", 4}};
  const ParsedShape s = parseShapeField(doc, "shape", 100);
  // Crisp children only: the node combines their memberships (geometry/field/smooth_csg_field.h).
  const auto* node = dynamic_cast<const MembershipCsgField*>(s.field.get());
  ASSERT_NE(node, nullptr);
  EXPECT_EQ(node->nodeOperator().config().name, "bezier");
  EXPECT_EQ(node->nodeOperator().config().params.at("n"), 3.0);
  const auto* leaf = dynamic_cast<const SmoothedPartField*>(node->children()[0].get());
  ASSERT_NE(leaf, nullptr);
  EXPECT_EQ(leaf->range(), 0.2);
  EXPECT_NEAR(leaf->membership({1, 0, 0}), 0.5, 1e-12);  // the sphere's surface
  EXPECT_EQ(s.smoothOperatorPath, "shape.tree.operator");
  EXPECT_EQ(s.nodeCount, 3u);
  // Blends, and the default range: 10% of the smallest half-length (a1 = 1: 0.1).
  const ParsedShape e = parseShapeField(smoothUnion({{"name", "ext_max"}, {"delta", 0.1}}, {ball(1, 0), ball(1, 1.9)}),
                                        "shape", 100);
  const auto* blended = dynamic_cast<const MembershipCsgField*>(e.field.get());
  ASSERT_NE(blended, nullptr);
  EXPECT_DOUBLE_EQ(dynamic_cast<const SmoothedPartField&>(*blended->children()[1]).range(), 0.1);
  // zadeh stays the exact Boolean.
  EXPECT_TRUE(parseShapeField(smoothUnion({{"name", "zadeh"}}, {ball(1, 0), ball(1, 1.9)}), "shape", 100)
                  .smoothOperatorPath.empty());
}

TEST(ShapeJson, BadSmoothNodeParametersNameTheirPath) {
  auto pathOf = [](json tree) { return errorOf({{"tree", std::move(tree)}}).path(); };
  json node = smoothUnion({{"name", "bezier"}, {"n", 0}}, {ball(1, 0), ball(1, 1)})["tree"];
  EXPECT_EQ(pathOf(node), "shape.tree.operator.n");
  node["operator"] = {{"name", "polynomial"}};  // a step is no node operator
  EXPECT_EQ(pathOf(node), "shape.tree.operator.name");
  node["operator"] = {{"name", "bezier"}};
  for (double bad : {0.0, -1.0}) {
    node["range"] = bad;
    EXPECT_EQ(errorOf({{"tree", node}}).code(), errc::kInvalidParameter);
    EXPECT_EQ(pathOf(node), "shape.tree.range");
  }
  node["range"] = "wide";
  EXPECT_EQ(pathOf(node), "shape.tree.range");
  node.erase("range");
  node["step"] = {{"name", "polynomial"}, {"n", 99}};
  EXPECT_EQ(pathOf(node), "shape.tree.step.n");
  node["step"] = {{"name", "rising_cutoff"}};  // step(0) != 1/2
  EXPECT_EQ(pathOf(node), "shape.tree.step.name");
  node["step"] = {{"name", "polynomial"}, {"epsilon", 2}};  // the range is the node's
  EXPECT_EQ(pathOf(node), "shape.tree.step.epsilon");
  // range and step belong to smooth operators only.
  json zadeh = smoothUnion({{"name", "zadeh"}}, {ball(1, 0), ball(1, 1)})["tree"];
  zadeh["range"] = 0.1;
  EXPECT_EQ(pathOf(zadeh), "shape.tree.range");
  // Nested nodes report their own path.
  json nested = {{"op", "union"}, {"children", {ball(1, 0), node}}};
  EXPECT_EQ(pathOf(nested), "shape.tree.children[1].step.epsilon");
}

// End to end: parse, then the envelope grid of a blended union of two overlapping spheres.
// Crisp parts under a smooth node combine as memberships μ (geometry/field/smooth_csg_field.h), read as
// Π = min(1, 2μ), N = max(0, 2μ − 1) (geometry/field/membership_field.h): lower(α) = {μ ≥ 1 − α/2} and
// upper(α) = {μ ≥ α/2}, nested (lower ⊆ upper at every α), one blended shape at α = 1.
TEST(ShapeJson, BlendedUnionEvaluatesToNestedFuzzyVolumes) {
  json doc = smoothUnion({{"name", "ext_max"}}, {ball(1, 0), ball(1, 1.9)});
  doc["tree"]["range"] = 0.3;
  const ParsedShape blended = parseShapeField(doc, "shape", 100);
  const ParsedShape zadeh = parseShapeField(smoothUnion({{"name", "zadeh"}}, {ball(1, 0), ball(1, 1.9)}), "shape", 100);
  const std::vector<double> alphas{0.0, 0.25, 0.5, 0.75, 1.0};
  const auto volumes = EnvelopeGrid::build(*blended.field, 0.05).volumes(alphas);
  const double zadehCore = EnvelopeGrid::build(*zadeh.field, 0.05).volumes({1.0})[0].upper_volume;
  for (size_t i = 0; i < volumes.size(); ++i) {
    EXPECT_LE(volumes[i].lower_volume, volumes[i].upper_volume) << alphas[i];
    if (i > 0) {  // nested in α: upper shrinks, lower grows
      EXPECT_LE(volumes[i].upper_volume, volumes[i - 1].upper_volume) << alphas[i];
      EXPECT_GE(volumes[i].lower_volume, volumes[i - 1].lower_volume) << alphas[i];
    }
  }
  // One shape at α = 1 (lower(1) = {μ > 1/2}, upper(1) = {μ ≥ 1/2}: equal up to voxels at exactly 1/2).
  EXPECT_NEAR(volumes[4].lower_volume, volumes[4].upper_volume, 1e-3 * volumes[4].upper_volume);
  EXPECT_GT(volumes[4].upper_volume, zadehCore);                   // Ext_max grows the union
  EXPECT_GT(volumes[0].upper_volume, volumes[4].upper_volume);     // graded: the levels differ
  EXPECT_LT(volumes[2].lower_volume, volumes[4].lower_volume);
}

// A fuzzy child puts the node in the (Π, N) world; crisp-only nodes combine memberships.
TEST(ShapeJson, SmoothNodesWithAFuzzyChildCombinePairs) {
  json fuzzy = {{"part", {{"params", {{"a1", {{"tri", {0.8, 1.0, 1.2}}}}}}}}, {"transform", {{"translate", {1.9, 0, 0}}}}};
  const ParsedShape mixed = parseShapeField(smoothUnion({{"name", "bezier"}}, {ball(1, 0), fuzzy}), "shape", 100);
  const auto* node = dynamic_cast<const SmoothCsgField*>(mixed.field.get());
  ASSERT_NE(node, nullptr);
  EXPECT_NE(dynamic_cast<const SmoothedPartField*>(node->children()[0].get()), nullptr);
  EXPECT_EQ(dynamic_cast<const SmoothedPartField*>(node->children()[1].get()), nullptr);
}

}  // namespace
}  // namespace fsdb
