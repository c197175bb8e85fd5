// query/document/bezier_json: fuzzy Bézier curves, surfaces and their stored documents from JSON, with
// the JSON path of every bad value and the limits named.
#include "query/document/bezier_json.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

using nlohmann::json;

const BezierJsonLimits kLimits{4, "max_control_points", 3, "max_curve_points"};

TEST(BezierJson, ParsesFuzzyControlPointsAndWeights) {
  const FuzzyBezierCurve c = parseBezierCurve(
      json::parse(R"({"control_points":[[{"tri":[0,1,2]},0,1],[2,"about 3",{"trap":[0,1,2,3]}]],"weights":[1,{"tri":[1,2,3]}]})"),
      "", kLimits);
  ASSERT_EQ(c.controlPoints.size(), 2u);
  EXPECT_EQ(c.controlPoints[0][0], FuzzyNumber::triangular(0, 1, 2));
  EXPECT_EQ(c.controlPoints[1][2], FuzzyNumber::trapezoidal(0, 1, 2, 3));
  EXPECT_EQ(c.weights[1], FuzzyNumber::triangular(1, 2, 3));
  // Round trip through curveToJson.
  const FuzzyBezierCurve back = parseBezierCurve(curveToJson(c), "", kLimits);
  EXPECT_EQ(back.controlPoints, c.controlPoints);
  EXPECT_EQ(back.weights, c.weights);
  EXPECT_EQ(controlPointsToJson(c.controlPoints), curveToJson(c)["control_points"]);
}

TEST(BezierJson, ParsesSurfacesAndStoredDocuments) {
  const json grid = json::parse(R"([[[0,0,0],[1,0,{"tri":[0,1,2]}]],[[0,1,0],[1,1,0]]])");
  const FuzzyBezierSurface s = parseSurfaceDocument({{"kind", "surface"}, {"name", "p"}, {"bezier", {{"control_grid", grid}}}}, "",
                                                    kLimits);
  EXPECT_EQ(s.controlGrid.size(), 2u);
  EXPECT_EQ(s.controlGrid[0][1][2], FuzzyNumber::triangular(0, 1, 2));
}

TEST(BezierJson, SurfaceErrorsCarryTheJsonPath) {
  expectError([] { parseSurfaceDocument(json::parse(R"({"bezier":{"control_grid":[[[0],[1]],[[0],[1]],[[2]]]}})"), "", kLimits); },
              errc::kLimitExceeded, "bezier.control_grid");
  expectError([] { parseSurfaceDocument(json::parse(R"({"bezier":{"control_grid":[[[0],[1]],[[0]]]}})"), "", kLimits); },
              errc::kInvalidDocument, "bezier.control_grid[1]");
}

TEST(BezierJson, ParametersAndDefuzzifiers) {
  EXPECT_EQ(parseParameterList(json::parse("[0,0.5,1]"), "u", kLimits), (std::vector<double>{0, 0.5, 1}));
  expectInvalidParameter([] { parseParameterList(json::parse("[0,2]"), "u", kLimits); }, "u[1]");
  expectError([] { parseParameterList(json::parse("[0,0,0,0]"), "u", kLimits); }, errc::kLimitExceeded, "u");
  const auto uv = parseUvList(json::parse("[[0,1],[0.5,0.25]]"), "uv", kLimits);
  EXPECT_EQ(uv[1][1], 0.25);
  expectError([] { parseUvList(json::parse("[[0]]"), "uv", kLimits); }, errc::kInvalidDocument, "uv[0]");
  expectInvalidParameter([] { parseUvList(json::parse("[[0,-1]]"), "uv", kLimits); }, "uv[0][1]");
  EXPECT_EQ(parseUnitNumber(0.25, "alpha"), 0.25);
  expectInvalidParameter([] { parseUnitNumber(1.5, "alpha"); }, "alpha");
  EXPECT_EQ(parseDefuzzifier("centroid", "method"), Defuzzifier::kCentroid);
  EXPECT_EQ(parseDefuzzifier("largest_of_maxima", "method"), Defuzzifier::kLargestOfMaxima);
  expectInvalidParameter([] { parseDefuzzifier("mode", "method"); }, "method");
}

}  // namespace
}  // namespace fsdb
