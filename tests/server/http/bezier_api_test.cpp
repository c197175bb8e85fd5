// Fuzzy Bézier curves and surfaces over HTTP against the real `fsdb serve` (docs/api.md §6;
// Sarwar & Akram): evaluate, elevate, defuzzify, surfaces, stored curves and surfaces (CRUD, names,
// versions, bulk), the SVG and mesh exports, the limits, and errors with their JSON paths.
#include <gtest/gtest.h>

#include <sstream>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

// A quadratic with fuzzy x of the first point and fuzzy y of the middle one.
json arcPoints() {
  return json::parse(R"([[{"tri":[0,1,2]},0],[2,{"tri":[1,2,4]}],[4,0]])");
}

json patchGrid() {
  return json::parse(R"([[[0,0,0],[1,0,{"tri":[0,1,2]}]],[[0,1,0],[1,1,0]]])");
}

class BezierApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server = new ServerProcess({"--max-control-points", "8", "--max-curve-points", "50"});
  }
  static void TearDownTestSuite() { delete server; }
  static ServerProcess* server;

  static void expectError(const ServerProcess::Reply& r, int status, const std::string& code, const std::string& path) {
    EXPECT_EQ(r.status, status) << r.body;
    EXPECT_EQ(r.json["error"]["code"], code) << r.body;
    EXPECT_EQ(r.json["error"]["path"], path) << r.body;
  }
};
ServerProcess* BezierApi::server = nullptr;

TEST_F(BezierApi, EvaluatesLowerCrispAndUpperCurves) {
  auto r = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", {0, 0.5, 1}}, {"alpha", 0.5}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["degree"], 2);
  EXPECT_EQ(r.json["rational"], false);
  const json& p = r.json["points"];
  ASSERT_EQ(p.size(), 3u);
  // u = 0: the cut of tri(0,1,2) at 0.5 is [0.5, 1.5] (Sarwar & Akram, eq. 3).
  EXPECT_EQ(p[0]["lower"], json({0.5, 0.0}));
  EXPECT_EQ(p[0]["crisp"], json({1.0, 0.0}));
  EXPECT_EQ(p[0]["upper"], json({1.5, 0.0}));
  // u = 0.5: B = (1/4, 1/2, 1/4); y cut of tri(1,2,4) at 0.5 is [1.5, 3].
  EXPECT_DOUBLE_EQ(p[1]["lower"][1].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(p[1]["upper"][1].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(p[1]["crisp"][0].get<double>(), 2.25);
  EXPECT_EQ(p[2]["u"], 1.0);
  EXPECT_EQ(p[2]["crisp"], json({4.0, 0.0}));
}

// Coordinates near the double range: the crisp curve was null ((lo + hi) / 2 overflowed); an
// evaluation that does overflow is 422 domain_error, never a null in a 200.
TEST_F(BezierApi, HugeCoordinatesAreFiniteOrRefused) {
  auto r = server->post("/curves/bezier/evaluate", json{{"control_points", {{1e308, 1e308}, {1e308, -1e308}}}, {"u", {0.5}}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["points"][0]["crisp"], json({1e308, 0.0})) << r.body;
  const json coordinate = json::object({{"tri", {-1e308, 0, 1e308}}}), weight = json::object({{"tri", {1e-300, 1, 1e300}}});
  const json wide = json::array({json::array({coordinate, 1}), json::array({coordinate, 1})});
  const json weights = json::array({weight, weight});
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", wide}, {"weights", weights}, {"u", {0.5}}}),
              422, "domain_error", "control_points");
}

TEST_F(BezierApi, AlphaDefaultsToTheSupport) {
  auto r = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", {0}}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["alpha"], 0.0);
  EXPECT_EQ(r.json["points"][0]["lower"], json({0.0, 0.0}));
}

TEST_F(BezierApi, RationalWithEqualWeightsMatchesThePolynomialCurve) {
  const json u = {0.1, 0.4, 0.9};
  auto poly = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", u}, {"alpha", 0.3}});
  auto rat = server->post("/curves/bezier/evaluate",
                          json{{"control_points", arcPoints()}, {"weights", {2, 2, 2}}, {"u", u}, {"alpha", 0.3}});
  ASSERT_EQ(rat.status, 200) << rat.body;
  EXPECT_EQ(rat.json["rational"], true);
  for (size_t i = 0; i < u.size(); ++i)
    for (const char* b : {"lower", "crisp", "upper"})
      for (size_t c = 0; c < 2; ++c)
        EXPECT_NEAR(rat.json["points"][i][b][c].get<double>(), poly.json["points"][i][b][c].get<double>(), 1e-12);
  // Fuzzy weights widen the band around the crisp curve.
  auto fuzzy = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()},
                                                            {"weights", json::parse(R"([1,{"tri":[0.5,1,3]},1])")},
                                                            {"u", {0.4}}});
  ASSERT_EQ(fuzzy.status, 200) << fuzzy.body;
  EXPECT_LT(fuzzy.json["points"][0]["lower"][1].get<double>(), poly.json["points"][1]["lower"][1].get<double>());
}

TEST_F(BezierApi, ElevationKeepsTheCurve) {
  auto e = server->post("/curves/bezier/elevate", json{{"control_points", arcPoints()}, {"times", 2}});
  ASSERT_EQ(e.status, 200) << e.body;
  EXPECT_EQ(e.json["degree"], 4);
  ASSERT_EQ(e.json["control_points"].size(), 5u);
  EXPECT_EQ(e.json["control_points"][0], arcPoints()[0]);
  const json u = {0, 0.25, 0.6, 1};
  auto a = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", u}, {"alpha", 0.2}});
  auto b = server->post("/curves/bezier/evaluate",
                        json{{"control_points", e.json["control_points"]}, {"u", u}, {"alpha", 0.2}});
  ASSERT_EQ(b.status, 200) << b.body;
  for (size_t i = 0; i < u.size(); ++i)
    for (const char* bound : {"lower", "crisp", "upper"})
      for (size_t c = 0; c < 2; ++c)
        EXPECT_NEAR(a.json["points"][i][bound][c].get<double>(), b.json["points"][i][bound][c].get<double>(), 1e-12);
  // Default times is 1; fuzzy weights cannot be elevated exactly.
  EXPECT_EQ(server->post("/curves/bezier/elevate", json{{"control_points", arcPoints()}}).json["degree"], 3);
  expectError(server->post("/curves/bezier/elevate", json{{"control_points", arcPoints()},
                                                          {"weights", json::parse(R"([1,{"tri":[1,2,3]},1])")}}),
              422, "invalid_parameter", "weights[1]");
  expectError(server->post("/curves/bezier/elevate", json{{"control_points", arcPoints()}, {"times", -1}}), 422,
              "invalid_parameter", "times");
  expectError(server->post("/curves/bezier/elevate", json{{"control_points", arcPoints()}, {"times", 6}}), 413,
              "limit_exceeded", "times");
}

TEST_F(BezierApi, DefuzzifiesCurvesAndGrids) {
  auto r = server->post("/curves/bezier/defuzzify", json{{"control_points", arcPoints()}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["method"], "centroid");
  EXPECT_DOUBLE_EQ(r.json["control_points"][1][1].get<double>(), 7.0 / 3);  // (1 + 2 + 4) / 3
  auto m = server->post("/curves/bezier/defuzzify",
                        json{{"control_points", arcPoints()}, {"weights", {1, {{"tri", {1, 2, 6}}}, 1}},
                             {"method", "mean_of_maxima"}});
  ASSERT_EQ(m.status, 200) << m.body;
  EXPECT_EQ(m.json["control_points"][1][1], 2.0);
  EXPECT_EQ(m.json["weights"][1], 2.0);
  auto g = server->post("/curves/bezier/defuzzify", json{{"control_grid", patchGrid()}});
  ASSERT_EQ(g.status, 200) << g.body;
  EXPECT_EQ(g.json["control_grid"][0][1], json({1.0, 0.0, 1.0}));
  expectError(server->post("/curves/bezier/defuzzify", json{{"control_points", arcPoints()}, {"method", "mode"}}), 422,
              "invalid_parameter", "method");
  expectError(server->post("/curves/bezier/defuzzify", json{{"control_points", arcPoints()}, {"control_grid", patchGrid()}}),
              422, "invalid_document", "control_grid");
}

TEST_F(BezierApi, EvaluatesSurfaces) {
  auto r = server->post("/surfaces/bezier/evaluate",
                        json{{"control_grid", patchGrid()}, {"uv", {{0.5, 0.5}, {0, 1}}}, {"alpha", 0.5}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["degree"], json({1, 1}));
  const json& p = r.json["points"][0];
  EXPECT_EQ(p["u"], 0.5);
  EXPECT_EQ(p["v"], 0.5);
  EXPECT_DOUBLE_EQ(p["lower"][2].get<double>(), 0.125);  // 1/4 of the cut [0.5, 1.5]
  EXPECT_DOUBLE_EQ(p["crisp"][2].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(p["upper"][2].get<double>(), 0.375);
  // (u, v) = (0, 1): the corner P_01 (row 0 runs along v), z the core of tri(0,1,2).
  EXPECT_EQ(r.json["points"][1]["crisp"], json({1.0, 0.0, 1.0}));
}

TEST_F(BezierApi, ElevatesSurfacesAndGivesIsoCurves) {
  auto e = server->post("/surfaces/bezier/elevate", json{{"control_grid", patchGrid()}, {"times_u", 1}, {"times_v", 0}});
  ASSERT_EQ(e.status, 200) << e.body;
  EXPECT_EQ(e.json["degree"], json({2, 1}));
  ASSERT_EQ(e.json["control_grid"].size(), 3u);
  const json uv = {{0.3, 0.6}, {1, 0}};
  auto a = server->post("/surfaces/bezier/evaluate", json{{"control_grid", patchGrid()}, {"uv", uv}, {"alpha", 0.25}});
  auto b = server->post("/surfaces/bezier/evaluate", json{{"control_grid", e.json["control_grid"]}, {"uv", uv}, {"alpha", 0.25}});
  ASSERT_EQ(b.status, 200) << b.body;
  for (size_t i = 0; i < uv.size(); ++i)
    for (const char* bound : {"lower", "crisp", "upper"})
      for (size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(a.json["points"][i][bound][c].get<double>(), b.json["points"][i][bound][c].get<double>(), 1e-12);
  // Default 1 and 1: 3 x 3 = 9 control points are over max_control_points = 8 here.
  expectError(server->post("/surfaces/bezier/elevate", json{{"control_grid", patchGrid()}}), 413, "limit_exceeded",
              "times_u");

  // The u-curve at v = 0.6, evaluated at u = 0.3, is the surface point (0.3, 0.6).
  auto iso = server->post("/surfaces/bezier/iso", json{{"control_grid", patchGrid()}, {"v", 0.6}});
  ASSERT_EQ(iso.status, 200) << iso.body;
  EXPECT_EQ(iso.json["degree"], 1);
  EXPECT_EQ(iso.json["fixed"], json({{"v", 0.6}}));
  auto onIso = server->post("/curves/bezier/evaluate",
                            json{{"control_points", iso.json["control_points"]}, {"u", {0.3}}, {"alpha", 0.25}});
  ASSERT_EQ(onIso.status, 200) << onIso.body;
  for (const char* bound : {"lower", "crisp", "upper"})
    for (size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(onIso.json["points"][0][bound][c].get<double>(), a.json["points"][0][bound][c].get<double>(), 1e-12);
  auto isoV = server->post("/surfaces/bezier/iso", json{{"control_grid", patchGrid()}, {"u", 0}});
  ASSERT_EQ(isoV.status, 200) << isoV.body;
  EXPECT_EQ(isoV.json["control_points"], patchGrid()[0]);  // u = 0: the first row
  expectError(server->post("/surfaces/bezier/iso", json{{"control_grid", patchGrid()}}), 422, "invalid_document", "u");
  expectError(server->post("/surfaces/bezier/iso", json{{"control_grid", patchGrid()}, {"u", 0}, {"v", 1}}), 422,
              "invalid_document", "v");
  expectError(server->post("/surfaces/bezier/iso", json{{"control_grid", patchGrid()}, {"v", 3}}), 422,
              "invalid_parameter", "v");
}

TEST_F(BezierApi, ErrorsNameTheJsonPath) {
  expectError(server->post("/curves/bezier/evaluate",
                           json{{"control_points", json::parse(R"([[0,0],[1,{"tri":[2,1,3]}]])")}, {"u", {0}}}),
              422, "invalid_document", "control_points[1][1].tri[1]");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", json::parse("[[0,0],[1]]")}, {"u", {0}}}),
              422, "invalid_document", "control_points[1]");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", {0, 1.5}}}), 422,
              "invalid_parameter", "u[1]");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", {0}}, {"alpha", 2}}),
              422, "invalid_parameter", "alpha");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}}), 422, "invalid_document",
              "u");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", {0}}, {"uu", 1}}), 422,
              "invalid_document", "uu");
  expectError(server->post("/curves/bezier/evaluate",
                           json{{"control_points", arcPoints()}, {"weights", {1, 0, 1}}, {"u", {0}}}),
              422, "invalid_document", "weights[1]");
  expectError(server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"weights", {1}}, {"u", {0}}}),
              422, "invalid_document", "weights");
  expectError(server->post("/surfaces/bezier/evaluate",
                           json{{"control_grid", json::parse("[[[0,0,0],[1,0,0]],[[0,1,0]]]")}, {"uv", {{0, 0}}}}),
              422, "invalid_document", "control_grid[1]");
  expectError(server->post("/surfaces/bezier/evaluate", json{{"control_grid", patchGrid()}, {"uv", {{0.5}}}}), 422,
              "invalid_document", "uv[0]");
  expectError(server->post("/curves/bezier/evaluate", std::string("{")), 400, "malformed_json", "body");
  // The routes do not collide with /curves/{id}.
  expectError(server->get("/curves/bezier"), 422, "invalid_parameter", "id");
  EXPECT_EQ(server->get("/curves/bezier/evaluate").status, 405);
}

TEST_F(BezierApi, LimitsAnswer413NamingTheLimit) {
  json many = json::array();
  for (int i = 0; i < 9; ++i) many.push_back({i, 0});
  auto r = server->post("/curves/bezier/evaluate", json{{"control_points", many}, {"u", {0}}});
  expectError(r, 413, "limit_exceeded", "control_points");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_control_points=8"), std::string::npos);
  json us = json::array();
  for (int i = 0; i < 51; ++i) us.push_back(i / 51.0);
  r = server->post("/curves/bezier/evaluate", json{{"control_points", arcPoints()}, {"u", us}});
  expectError(r, 413, "limit_exceeded", "u");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_curve_points=50"), std::string::npos);
  json grid = json::array();
  for (int i = 0; i < 3; ++i) grid.push_back({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  expectError(server->post("/surfaces/bezier/evaluate", json{{"control_grid", grid}, {"uv", {{0, 0}}}}), 413,
              "limit_exceeded", "control_grid");
  // Stored curves and surfaces obey --max-control-points too (not --max-nodes).
  r = server->post("/curves", json{{"name", "too-many"}, {"bezier", {{"control_points", many}}}});
  expectError(r, 413, "limit_exceeded", "bezier.control_points");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_control_points=8"), std::string::npos) << r.body;
  r = server->post("/surfaces", json{{"name", "too-many"}, {"bezier", {{"control_grid", grid}}}});
  expectError(r, 413, "limit_exceeded", "bezier.control_grid");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_control_points=8"), std::string::npos) << r.body;
  EXPECT_EQ(server->get("/health").status, 200);  // and the server keeps serving
}

// --max-nodes bounds a shape's CSG nodes only: a small one leaves stored curves alone.
TEST(BezierLimits, MaxNodesDoesNotLimitStoredCurves) {
  ServerProcess small({"--max-nodes", "2"});
  json points = json::array();
  for (int i = 0; i < 5; ++i) points.push_back({i, i % 2});
  auto r = small.post("/curves", json{{"name", "five"}, {"bezier", {{"control_points", points}}}});
  EXPECT_EQ(r.status, 201) << r.body;
  r = small.post("/shapes", json::parse(R"({"name":"s","tree":{"op":"union","children":[{"part":{"params":{"a1":1}}},{"part":{"params":{"a1":2}}}]}})"));
  EXPECT_EQ(r.status, 413) << r.body;
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_nodes=2"), std::string::npos) << r.body;
}

TEST_F(BezierApi, StoresCurvesWithNamesAndVersions) {
  auto c = server->post("/curves", json{{"kind", "curve"}, {"name", "arc"}, {"bezier", {{"control_points", arcPoints()}}}});
  ASSERT_EQ(c.status, 201) << c.body;
  const int64_t id = c.json["id"];
  EXPECT_EQ(c.location, "/curves/" + std::to_string(id));
  EXPECT_EQ(c.json["kind"], "curve");
  auto v2 = server->put("/curves/" + std::to_string(id),
                        json{{"bezier", {{"control_points", arcPoints()}, {"weights", {1, 3, 1}}}}});
  ASSERT_EQ(v2.status, 200) << v2.body;
  EXPECT_EQ(v2.json["version"], 2);
  EXPECT_EQ(v2.json["name"], "arc");
  auto old = server->get("/curves/" + std::to_string(id) + "?version=1");
  EXPECT_FALSE(old.json["document"]["bezier"].contains("weights"));
  auto byName = server->get("/curves?name=arc");
  ASSERT_EQ(byName.json["items"].size(), 1u);
  EXPECT_EQ(byName.json["items"][0]["id"], id);
  // A curve is not a shape, and a stored curve is validated like a request.
  EXPECT_EQ(server->get("/shapes/" + std::to_string(id)).status, 404);
  expectError(server->post("/curves", json{{"name", "bad"}, {"bezier", {{"control_points", json::parse("[[0],[{\"tri\":[1,0,2]}]]")}}}}),
              422, "invalid_document", "bezier.control_points[1][0].tri[1]");
  expectError(server->post("/curves", json{{"name", "bad"}, {"fair", nullptr}}), 422, "invalid_document", "fair");
  expectError(server->post("/curves", json{{"name", "bad"}}), 422, "invalid_document", "bezier");
  expectError(server->post("/curves", json{{"kind", "surface"}, {"name", "bad"}, {"bezier", {{"control_points", arcPoints()}}}}),
              422, "invalid_document", "kind");
  expectError(server->post("/curves", json{{"name", "arc"}, {"bezier", {{"control_points", arcPoints()}}}}), 409,
              "conflict", "name");
  auto bulk = server->post("/curves/bulk",
                           "{\"name\":\"b1\",\"bezier\":{\"control_points\":[[0,0],[1,1]]}}\n{\"name\":\"b2\",\"bezier\":{}}\n",
                           "application/x-ndjson");
  ASSERT_EQ(bulk.status, 200) << bulk.body;
  EXPECT_EQ(bulk.json["imported"], 1);
  EXPECT_EQ(bulk.json["failed"], 1);
  EXPECT_EQ(server->get("/health").json["curves"], 2);
  auto d = server->del("/curves/" + std::to_string(id));
  ASSERT_EQ(d.status, 200) << d.body;
  EXPECT_EQ(server->get("/curves/" + std::to_string(id)).status, 404);
}

TEST_F(BezierApi, ExportsTheStoredCurveAsSvg) {
  auto c = server->post("/curves", json{{"name", "svg-arc"}, {"bezier", {{"control_points", arcPoints()}}}});
  ASSERT_EQ(c.status, 201) << c.body;
  const std::string base = "/curves/" + std::to_string(c.json["id"].get<int64_t>());
  auto r = server->get(base + "/svg?alpha=0.5&samples=3");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.contentType, "image/svg+xml");
  EXPECT_EQ(r.body.rfind("<svg", 0), 0u);
  // The three polylines through u = 0, 0.5, 1 (the values of EvaluatesLowerCrispAndUpperCurves).
  EXPECT_NE(r.body.find("id=\"lower\" stroke=\"#1f77b4\" points=\"0.5,0 2.125,0.75 4,0\""), std::string::npos) << r.body;
  EXPECT_NE(r.body.find("id=\"crisp\" stroke=\"#000000\" points=\"1,0 2.25,1 4,0\""), std::string::npos) << r.body;
  EXPECT_NE(r.body.find("id=\"upper\" stroke=\"#d62728\" points=\"1.5,0 2.375,1.5 4,0\""), std::string::npos) << r.body;
  expectError(server->get(base + "/svg?alpha=1.5"), 422, "invalid_parameter", "alpha");
  expectError(server->get(base + "/svg?samples=1"), 422, "invalid_parameter", "samples");
  expectError(server->get(base + "/svg?samples=51"), 413, "limit_exceeded", "samples");
  expectError(server->get("/curves/999999/svg"), 404, "not_found", "");
  // The default samples (101) is capped by max_curve_points (50 here).
  auto capped = server->get(base + "/svg");
  ASSERT_EQ(capped.status, 200) << capped.body;
  EXPECT_NE(capped.body.find(" 4,0\"/>"), std::string::npos);
}

TEST_F(BezierApi, StoresSurfacesAndExportsTheirMesh) {
  auto s = server->post("/surfaces", json{{"kind", "surface"}, {"name", "patch"}, {"bezier", {{"control_grid", patchGrid()}}}});
  ASSERT_EQ(s.status, 201) << s.body;
  const std::string base = "/surfaces/" + std::to_string(s.json["id"].get<int64_t>());
  EXPECT_EQ(server->get("/surfaces?name=patch").json["items"].size(), 1u);
  auto upper = server->get(base + "/mesh?alpha=0.5&bound=upper&resolution=2");
  ASSERT_EQ(upper.status, 200) << upper.body;
  EXPECT_EQ(upper.contentType, "model/obj");
  int vertices = 0, faces = 0;
  std::istringstream lines(upper.body);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("f ", 0) == 0) ++faces;
  }
  EXPECT_EQ(vertices, 9);
  EXPECT_EQ(faces, 8);
  // The corner (u, v) = (0, 1) is P_01 = (1, 0, tri(0,1,2)): z is the upper end of its cut at 0.5.
  EXPECT_NE(upper.body.find("\nv 1 0 1.5\n"), std::string::npos) << upper.body;
  auto crisp = server->get(base + "/mesh");  // default resolution 32, capped at 6 here
  ASSERT_EQ(crisp.status, 200) << crisp.body;
  EXPECT_NE(crisp.body.find("\nv 1 0 1\n"), std::string::npos) << crisp.body;
  auto stl = server->get(base + "/mesh?format=stl&resolution=1");
  EXPECT_EQ(stl.contentType, "model/stl");
  EXPECT_EQ(stl.body.size(), 84u + 2 * 50u);
  expectError(server->get(base + "/mesh?bound=middle"), 422, "invalid_parameter", "bound");
  expectError(server->get(base + "/mesh?format=ply"), 422, "invalid_parameter", "format");
  expectError(server->get(base + "/mesh?resolution=7"), 413, "limit_exceeded", "resolution");
  expectError(server->post("/surfaces", json{{"name", "ragged"}, {"bezier", {{"control_grid", json::parse("[[[0,0,0],[1,0,0]],[[0,1,0]]]")}}}}),
              422, "invalid_document", "bezier.control_grid[1]");
  EXPECT_EQ(server->get("/health").json["surfaces"].get<int>(), 1);
}

}  // namespace
