// POST /curves/fair (the fair curves of Bernardes, Wu & D'Ottaviano; docs/api.md §6) against the
// real `fsdb serve`.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

class FairCurveApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server = new ServerProcess(); }
  static void TearDownTestSuite() { delete server; }
  static ServerProcess* server;

  static json post(const json& body, int expectStatus = 200) {
    auto r = server->post("/curves/fair", body);
    EXPECT_EQ(r.status, expectStatus) << r.body;
    return r.json;
  }
  static void expectError(const json& body, int status, const std::string& code, const std::string& path) {
    const json e = post(body, status);
    EXPECT_EQ(e["error"]["code"], code) << e.dump();
    EXPECT_EQ(e["error"]["path"], path) << e.dump();
  }
};
ServerProcess* FairCurveApi::server = nullptr;

double distance(const json& a, const json& b) {
  return std::hypot(a[0].get<double>() - b[0].get<double>(), a[1].get<double>() - b[1].get<double>());
}

TEST_F(FairCurveApi, ClosedFourPointsGiveRankedCandidatesThroughEveryPoint) {
  const json points = {{0, 0}, {-5, -1}, {-3, -4}, {1, -1}};
  const json r =
      post({{"points", points}, {"closed", true}, {"behavior", "undulant"}, {"samples", 9}, {"max_candidates", 20}});
  const json& c = r["candidates"];
  ASSERT_GE(c.size(), 8u) << r.dump();
  std::set<std::string> distinct;
  for (size_t k = 0; k < c.size(); ++k) {
    if (k > 0) {
      EXPECT_GE(c[k - 1]["score"].get<double>(), c[k]["score"].get<double>());
    }
    distinct.insert(c[k]["angles_deg"].dump());
    const json& curve = c[k]["curve"];
    ASSERT_EQ(curve.size(), 4u * 8 + 1);
    for (size_t i = 0; i < 4; ++i) EXPECT_LT(distance(curve[8 * i], points[i]), 1e-9) << k << " " << i;
    EXPECT_LT(distance(curve.back(), points[0]), 1e-9);
    ASSERT_EQ(c[k]["angles_deg"].size(), 4u);
  }
  EXPECT_EQ(distinct.size(), c.size());
  EXPECT_EQ(r["first_estimation_deg"].size(), 4u);
  EXPECT_EQ(r["behavior"], "undulant");
}

TEST_F(FairCurveApi, OpenCurveWithRelationsAndThreshold) {
  const json body = {{"points", {{100, 440}, {200, 150}, {550, 450}}}, {"relations", {"sharper", "smoother"}}};
  const json all = post(body);
  ASSERT_FALSE(all["candidates"].empty());
  const auto& radii = all["radii"];
  EXPECT_LT(radii[1].get<double>(), radii[0].get<double>());  // P2 sharper than P1
  EXPECT_GT(radii[2].get<double>(), radii[1].get<double>());  // P3 smoother than P2
  EXPECT_EQ(all["behavior"], "no_inflection");
  json high = body;
  high["alpha_threshold"] = 0.6;
  const json highAnswer = post(high);  // kept: a range-for over post(high)["candidates"] would dangle
  for (const json& c : highAnswer["candidates"]) EXPECT_GE(c["membership"].get<double>(), 0.6);
  const json& curve = all["candidates"][0]["curve"];
  EXPECT_EQ(curve.size(), 2u * 31 + 1);  // default 32 samples per piece
  EXPECT_LT(distance(curve.front(), body["points"][0]), 1e-9);
  EXPECT_LT(distance(curve.back(), body["points"][2]), 1e-9);
}

// Integer fields take integral doubles as the Bézier routes do (query/json/json_body.h integralNumber):
// samples 32.0 is samples 32; 2.5 stays refused (FairCurveApi errors).
TEST_F(FairCurveApi, IntegralDoublesAreIntegers) {
  json body = {{"points", {{100, 440}, {200, 150}, {550, 450}}}, {"samples", 9}, {"max_candidates", 3}};
  const json asInteger = post(body);
  body["samples"] = 9.0;
  body["max_candidates"] = 3.0;
  EXPECT_EQ(post(body), asInteger);
  auto e = server->post("/curves/bezier/elevate", json{{"control_points", {{0, 0}, {2, 2}, {4, 0}}}, {"times", 2.0}});
  EXPECT_EQ(e.status, 200) << e.body;
}

TEST_F(FairCurveApi, BadInputAnswers422WithTheJsonPath) {
  expectError({{"points", {{0, 0}, {1, "a"}}}}, 422, "invalid_document", "points[1][1]");
  expectError({{"points", {{0, 0}, {1, 1, 1}}}}, 422, "invalid_document", "points[1]");
  expectError({{"points", {{0, 0}, {0, 0}}}}, 422, "invalid_parameter", "points[1]");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"closed", true}}, 422, "invalid_parameter", "points");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"closed", 1}}, 422, "invalid_document", "closed");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"relations", {"rounder"}}}, 422, "invalid_parameter", "relations[0]");
  expectError({{"points", {{0, 0}, {1, 1}, {2, 0}}}, {"relations", {"smoother"}}}, 422, "invalid_parameter",
              "relations");
  expectError(
      {{"points", {{0, 0}, {1, 1}, {2, 0}}}, {"closed", true}, {"relations", {"sharper", "sharper", "sharper"}}}, 422,
      "invalid_parameter", "relations");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"alpha_threshold", 2}}, 422, "invalid_parameter", "alpha_threshold");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"samples", 1}}, 422, "invalid_parameter", "samples");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"samples", 2.5}}, 422, "invalid_document", "samples");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"behavior", "wavy"}}, 422, "invalid_parameter", "behavior");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"max_candidates", 0}}, 422, "invalid_parameter", "max_candidates");
  expectError({{"points", {{0, 0}, {1, 1}}}, {"color", "red"}}, 422, "invalid_document", "color");
  expectError(json::object(), 422, "invalid_document", "points");
  auto r = server->post("/curves/fair", std::string("{\"points\": ["));
  EXPECT_EQ(r.status, 400);
}

TEST_F(FairCurveApi, LimitsAnswer413NamingTheLimitAndTheServerKeepsServing) {
  json many = json::array();
  for (int i = 0; i <= 1000; ++i) many.push_back({i, i % 2});
  json e = post({{"points", many}}, 413);
  EXPECT_EQ(e["error"]["code"], "limit_exceeded");
  EXPECT_EQ(e["error"]["path"], "points");
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_fair_points=1000"), std::string::npos);
  e = post({{"points", {{0, 0}, {1, 1}}}, {"samples", 1001}}, 413);
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_fair_samples=1000"), std::string::npos);
  json big = json::array();
  for (int i = 0; i < 500; ++i) big.push_back({i, i % 2});
  e = post({{"points", big}, {"samples", 1000}, {"max_candidates", 100}}, 413);
  EXPECT_NE(e["error"]["message"].get<std::string>().find("max_fair_curve_points=1000000"), std::string::npos);
  EXPECT_EQ(server->get("/health").status, 200);
}

// Points further apart than the largest double have no representable radius: once the error
// named "magnitudes[0]", a field no request has.
TEST_F(FairCurveApi, UnrepresentableRadiiNameThePoints) {
  expectError({{"points", {{-1e308, 1e308}, {1e308, -1e308}}}}, 422, "invalid_parameter", "points");
  expectError({{"points", {{-1.5e308, 0}, {1.5e308, 0}, {0, 1e308}}}, {"closed", true}}, 422, "invalid_parameter",
              "points");
  // Representable points whose curve bulges beyond the largest double (y up to 1.79e308).
  const json beyond = post({{"points", {{0, 1.79e308}, {1e308, 1.79e308}}}}, 422);
  EXPECT_EQ(beyond["error"]["path"], "points") << beyond.dump();
  EXPECT_NE(beyond["error"]["message"].get<std::string>().find("leaves the range of doubles"), std::string::npos)
      << beyond.dump();
}

// Fuzz findings: these answered 200 with null (NaN) curve points. A closed curve through
// collinear points, points a subnormal distance apart and points near the largest double.
TEST_F(FairCurveApi, DegeneratePointsAnswerFiniteCurves) {
  for (const json& body : {json{{"points", {{0, 0}, {1, 1}, {2, 2}}}, {"closed", true}},
                           json{{"points", {{0, 0}, {5e-324, 0}}}}, json{{"points", {{1e308, 0}, {0, 0}}}},
                           // Near the double range, within it: computed in the points' own frame.
                           json{{"points", {{0, 0}, {1e308, 0}, {1e308, 1e308}}}},
                           json{{"points", {{-1e308, 0}, {1e308, 0}, {0, 1e308}}}, {"closed", true}}}) {
    const json r = post(body);
    ASSERT_FALSE(r["candidates"].empty()) << body.dump();
    for (const json& c : r["candidates"])
      for (const json& p : c["curve"]) {
        ASSERT_TRUE(p[0].is_number() && p[1].is_number()) << body.dump() << " " << p.dump();
        EXPECT_TRUE(std::isfinite(p[0].get<double>()) && std::isfinite(p[1].get<double>())) << body.dump();
      }
  }
  // Points too close for the size of the curve to tell apart once scaled.
  expectError({{"points", {{0, 0}, {1e300, 0}, {1e300, 5e-324}}}}, 422, "invalid_parameter", "points[2]");
}

}  // namespace
