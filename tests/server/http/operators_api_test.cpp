// GET /operators and POST /operators/evaluate against the real server.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

class OperatorsApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server = new ServerProcess(); }
  static void TearDownTestSuite() { delete server; }
  static ServerProcess* server;

  static json evaluate(const json& body, int expectStatus = 200) {
    auto r = server->post("/operators/evaluate", body);
    EXPECT_EQ(r.status, expectStatus) << r.body;
    return r.json;
  }
};
ServerProcess* OperatorsApi::server = nullptr;

TEST_F(OperatorsApi, CatalogueListsEveryOperatorOfTheSpec) {
  auto r = server->get("/operators");
  ASSERT_EQ(r.status, 200);
  std::set<std::string> names;
  for (const auto& op : r.json["operators"]) {
    names.insert(op["name"].get<std::string>());
    EXPECT_TRUE(op["kind"].is_string());
    EXPECT_TRUE(op["reference"].is_string());
    for (const auto& p : op["params"]) {
      EXPECT_TRUE(p["name"].is_string());
      EXPECT_TRUE(p["default"].is_number()) << op["name"] << "." << p["name"];
    }
  }
  for (const char* n : {"zadeh", "algebraic", "lukasiewicz", "dubois_prade", "einstein", "dombi", "hamacher", "weber",
                        "yager", "bezier", "smooth_and", "smooth_and_hat", "ext_max", "int_max"})
    EXPECT_TRUE(names.count(n)) << "missing operator " << n;
}

TEST_F(OperatorsApi, EvaluatesTNormsConormsAndDifferences) {
  json points = json::array({{0.2, 0.7}, {0.9, 0.4}, {1.0, 0.3}, {0.0, 0.8}});
  auto inter = evaluate({{"operator", {{"name", "zadeh"}}}, {"points", points}});
  auto uni = evaluate({{"operator", {{"name", "zadeh"}}}, {"op", "union"}, {"points", points}});
  auto diff = evaluate({{"operator", {{"name", "algebraic"}}}, {"op", "difference"}, {"points", points}});
  for (size_t i = 0; i < points.size(); ++i) {
    double x = points[i][0], y = points[i][1];
    EXPECT_DOUBLE_EQ(inter["values"][i].get<double>(), std::min(x, y));
    EXPECT_DOUBLE_EQ(uni["values"][i].get<double>(), std::max(x, y));
    EXPECT_NEAR(diff["values"][i].get<double>(), x * (1 - y), 1e-15);
  }
  EXPECT_EQ(inter["op"], "intersection");
}

TEST_F(OperatorsApi, BezierOperatorMatchesSeed000Equation6) {
  json points = json::array({{0.2, 0.7}, {0.5, 0.5}, {0.9, 0.1}});
  auto r = evaluate({{"operator", {{"name", "bezier"}, {"n", 2}}}, {"points", points}});
  for (size_t i = 0; i < points.size(); ++i) {
    double x = points[i][0], y = points[i][1];
    EXPECT_NEAR(r["values"][i].get<double>(), x * y * (1 + (1 - x) * (1 - y)), 1e-12);  // Li & Tian, eq. 6
  }
  EXPECT_TRUE(r["operator"]["n"].is_number_integer()) << r.dump();
  EXPECT_EQ(r["operator"]["n"], 2);
}

TEST_F(OperatorsApi, FillsDefaultsAndEvaluatesStepFunctionsOnScalars) {
  auto r = evaluate({{"operator", {{"name", "polynomial"}, {"n", 1}}}, {"points", {-2.0, -1.0, 0.0, 0.5, 3.0}}});
  std::vector<double> expect = {0, 0, 0.5, 0.75, 1};  // H_1 is the ramp (t+1)/2 on [-1, 1]
  for (size_t i = 0; i < expect.size(); ++i) EXPECT_NEAR(r["values"][i].get<double>(), expect[i], 1e-12);
  auto blend = evaluate({{"operator", {{"name", "ext_max"}}}, {"points", {{1.0, -1.0}}}});
  EXPECT_TRUE(blend["operator"].contains("step")) << blend.dump();
  EXPECT_EQ(blend["op"], "union");
}

TEST_F(OperatorsApi, RejectsUnknownNamesAndParametersOutOfRangeNamingThem) {
  auto r = evaluate({{"operator", {{"name", "yagr"}}}, {"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["code"], "unknown_name");
  EXPECT_EQ(r["error"]["path"], "operator.name");
  EXPECT_NE(r["error"]["message"].get<std::string>().find("yager"), std::string::npos) << r.dump();

  r = evaluate({{"operator", {{"name", "yager"}, {"k", 0.5}}}, {"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["code"], "invalid_parameter");
  EXPECT_EQ(r["error"]["path"], "operator.k");

  r = evaluate({{"operator", {{"name", "int_max"}, {"step", {{"name", "bspline"}, {"m", -3}}}}},
                {"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "operator.step.m");

  r = evaluate({{"operator", {{"name", "zadeh"}, {"bogus", 1}}}, {"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "operator.bogus");

  r = evaluate({{"operator", {{"name", "zadeh"}}}, {"points", {{0.1, 1.5}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "points[0][1]");

  r = evaluate({{"operator", {{"name", "zadeh"}}}, {"points", {{0.1}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "points[0]");

  r = evaluate({{"operator", {{"name", "zadeh"}}}, {"op", "xor"}, {"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "op");

  r = evaluate({{"points", {{0.1, 0.2}}}}, 422);
  EXPECT_EQ(r["error"]["path"], "operator");
  EXPECT_EQ(server->get("/health").status, 200);
}

TEST_F(OperatorsApi, AnswersAMillionPointsAndRefusesMore) {
  ServerProcess small({"--max-points", "10"});
  json points = json::array();
  for (int i = 0; i < 11; ++i) points.push_back({0.5, 0.5});
  auto r = small.post("/operators/evaluate", json{{"operator", {{"name", "zadeh"}}}, {"points", points}});
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(r.json["error"]["path"], "points");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_points=10"), std::string::npos);

  std::string big = "{\"operator\":{\"name\":\"einstein\"},\"points\":[";
  for (int i = 0; i < 1000000; ++i) big += (i ? ",[0.5,0.25]" : "[0.5,0.25]");
  big += "]}";
  auto ok = server->post("/operators/evaluate", big);
  ASSERT_EQ(ok.status, 200);
  ASSERT_EQ(ok.json["values"].size(), 1000000u);
  EXPECT_NEAR(ok.json["values"][999999].get<double>(), 0.125 / (2 - (0.75 - 0.125)), 1e-15);
}

}  // namespace
