// query/document/curve_document: a stored curve is a Bézier curve or a fair curve, exactly one, with the
// JSON path of every bad value (prefixed by the caller's) and the limits named.
#include "query/document/curve_document.h"
#include "query/document/bezier_json.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "tests/geometry/expect_error.h"

namespace fsdb {
namespace {

using nlohmann::json;

const BezierJsonLimits kLimits{4, "max_control_points", 3, "max_curve_points"};

TEST(CurveDocument, ReadsTheBezierForm) {
  const CurveDocument c = parseCurveDocument(
      {{"name", "c"}, {"meta", {{"by", "me"}}}, {"bezier", {{"control_points", {{0, 0}, {1, 1}}}}}}, "", kLimits);
  ASSERT_TRUE(c.bezier.has_value());
  EXPECT_FALSE(c.fair.has_value());
  EXPECT_EQ(c.bezier->degree(), 1u);
}

TEST(CurveDocument, ReadsTheFairFormAsTheRequestParserDoes) {
  const json fair = {{"points", {{0, 0}, {1, 1}, {2, 0}}}, {"relations", {"smoother", "sharper"}}, {"samples", 5}};
  const CurveDocument c = parseCurveDocument({{"kind", "curve"}, {"name", "f"}, {"fair", fair}}, "", kLimits);
  ASSERT_TRUE(c.fair.has_value());
  EXPECT_FALSE(c.bezier.has_value());
  const FairCurveRequest direct = parseFairCurveRequest(fair);
  ASSERT_EQ(c.fair->points.size(), direct.points.size());
  EXPECT_EQ(c.fair->points[2].x, 2.0);
  EXPECT_EQ(c.fair->relations, direct.relations);
  EXPECT_EQ(c.fair->samples, 5);
  EXPECT_FALSE(c.fair->closed);
}

// The designer's pick among a fair curve's ranked candidates (Bernardes, Wu & D'Ottaviano make the
// user part of the defuzzification): an index of the candidates the document's request yields.
TEST(CurveDocument, KeepsTheDesignersChosenCandidate) {
  const json fig7 = {
      {"points", {{0, 0}, {-5, -1}, {-3, -4}, {1, -1}}}, {"closed", true}, {"behavior", "undulant"}, {"samples", 5}};
  const size_t n = answerFairCurve(parseFairCurveRequest(fig7)).candidates.size();
  ASSERT_GE(n, 2u);
  const CurveDocument c = parseCurveDocument({{"fair", fig7}, {"chosen_candidate", 1}}, "", kLimits);
  ASSERT_TRUE(c.chosenCandidate.has_value());
  EXPECT_EQ(*c.chosenCandidate, 1u);
  EXPECT_FALSE(parseCurveDocument({{"fair", fig7}}, "", kLimits).chosenCandidate.has_value());
  // 2.0 is the integer 2 (the one rule for integer fields).
  EXPECT_EQ(*parseCurveDocument({{"fair", fig7}, {"chosen_candidate", n - 1.0}}, "", kLimits).chosenCandidate, n - 1);
  auto bad = [](const json& doc) {
    expectError([&] { parseCurveDocument(doc, "line", kLimits); }, errc::kInvalidDocument, "line.chosen_candidate");
  };
  bad({{"fair", fig7}, {"chosen_candidate", n}});
  bad({{"fair", fig7}, {"chosen_candidate", -1}});
  bad({{"fair", fig7}, {"chosen_candidate", 0.5}});
  bad({{"fair", fig7}, {"chosen_candidate", "1"}});
  bad({{"bezier", {{"control_points", {{0, 0}, {1, 1}}}}}, {"chosen_candidate", 0}});
  // R_alpha = 1 leaves no candidate to choose.
  json none = fig7;
  none["alpha_threshold"] = 1;
  bad({{"fair", none}, {"chosen_candidate", 0}});
}

TEST(CurveDocument, ErrorsCarryTheJsonPath) {
  auto bad = [](const char* text, const std::string& path, const char* code = errc::kInvalidDocument) {
    expectError([&] { parseCurveDocument(json::parse(text), "line", kLimits); }, code, path);
  };
  bad(R"({"name":"c"})", "line.bezier");
  // Not an object: invalid_document, not json's own iterator error (found by fuzz_curve_document).
  for (const char* notObject : {"[1]", "\"c\"", "3"}) {
    bad(notObject, "line");
    expectError([&] { parseSurfaceDocument(json::parse(notObject), "line", kLimits); }, errc::kInvalidDocument, "line");
  }
  bad(R"({"name":"c","fair":{"points":[[0,0],[1,1]]},"bezier":{"control_points":[[0]]}})", "line.fair");
  bad(R"({"name":"c","bezier":{"control_points":[[0,0],[{"tri":[1,0,2]},0]]}})",
      "line.bezier.control_points[1][0].tri[1]");
  bad(R"({"name":"c","bezier":{"control_points":[[0,0],[0]]}})", "line.bezier.control_points[1]");
  bad(R"({"name":"c","bezier":{"control_points":[[0,0,0,0]]}})", "line.bezier.control_points[0]");
  bad(R"({"name":"c","bezier":{"control_points":[[0]],"weights":[-1]}})", "line.bezier.weights[0]");
  bad(R"({"name":"c","bezier":{"control_points":[[0]],"weights":[]}})", "line.bezier.weights");
  bad(R"({"name":"c","bezier":{"control_points":[[0]],"degree":2}})", "line.bezier.degree");
  bad(R"({"name":"c","bezier":{"control_points":[[0],[1],[2],[3],[4]]}})", "line.bezier.control_points",
      errc::kLimitExceeded);
  bad(R"({"name":"c","bezier":[]})", "line.bezier");
  bad(R"({"name":"c","fair":{}})", "line.fair.points");
  bad(R"({"name":"c","fair":[]})", "line.fair");
  bad(R"({"name":"c","fair":{"points":[[0,0],[1,"x"]]}})", "line.fair.points[1][1]");
  bad(R"({"name":"c","fair":{"points":[[0,0],[1,1]],"relations":["rounder"]}})", "line.fair.relations[0]",
      errc::kInvalidParameter);
  bad(R"({"name":"c","fair":{"points":[[0,0],[1,1]],"flag":1}})", "line.fair.flag");
  bad(R"({"name":"c","fair":{"points":[[0,0],[0,0]]}})", "line.fair.points[1]", errc::kInvalidParameter);
  bad(R"({"name":"c","shape":{}})", "line.shape");
  FairCurveLimits small;
  small.maxPoints = 2;
  expectError(
      [&] { parseCurveDocument(json::parse(R"({"fair":{"points":[[0,0],[1,1],[2,0]]}})"), "", kLimits, small); },
      errc::kLimitExceeded, "fair.points");
}

}  // namespace
}  // namespace fsdb
