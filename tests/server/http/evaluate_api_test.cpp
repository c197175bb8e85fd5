// POST /evaluate and `fsdb eval` against the real binary: the fuzzy volume of fuzzy parts and
// CSG trees against closed forms, and the errors of bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "tests/server/shared_server.h"

using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;
double ballVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

json fuzzyBall(double r1, double r2, double r3, double x = 0) {
  return {{"kind", "part"},
          {"params", {{"a1", {{"tri", {r1, r2, r3}}}}}},
          {"transform", {{"translate", {x, 0, 0}}}}};
}

class EvaluateApi : public SharedServerTest<EvaluateApi> {
 public:
  static std::vector<std::string> serverArgs() { return {"--max-resolution", "200", "--max-nodes", "5"}; }
};

TEST_F(EvaluateApi, FuzzyBallVolumesFollowTheAlphaCutRadii) {
  auto r = server->post("/evaluate", json{{"shape", fuzzyBall(0.8, 1.0, 1.2)}, {"resolution", 96}, {"alphas", {0, 0.5, 1}}});
  ASSERT_EQ(r.status, 200) << r.body;
  ASSERT_EQ(r.json["alphas"].size(), 3u);
  for (const auto& level : r.json["alphas"]) {
    const double a = level["alpha"];
    const double lower = ballVolume(0.8 + 0.2 * a), upper = ballVolume(1.2 - 0.2 * a);
    EXPECT_NEAR(level["lower_volume"].get<double>(), lower, 0.03 * lower) << "alpha " << a;
    EXPECT_NEAR(level["upper_volume"].get<double>(), upper, 0.03 * upper) << "alpha " << a;
  }
  EXPECT_GT(r.json["active_voxels"].get<double>(), 0);
  EXPECT_GT(r.json["voxel_size"].get<double>(), 0);
  EXPECT_EQ(r.json["parts"], 1);
}

TEST_F(EvaluateApi, CrispDifferenceOfBallsMatchesTheLensFormula) {
  // Two crisp unit balls at distance 1: |A − B| = |A| − lens, lens = π(4R + d)(2R − d)²/12.
  json shape = {{"kind", "shape"},
                {"tree", {{"op", "difference"},
                          {"children", {{{"part", fuzzyBall(1, 1, 1)}}, {{"part", fuzzyBall(1, 1, 1, 1.0)}}}}}}};
  auto r = server->post("/evaluate", json{{"shape", shape}, {"resolution", 128}, {"alphas", {0.5, 1}}});
  ASSERT_EQ(r.status, 200) << r.body;
  const double lens = kPi * (4 + 1) * 1 / 12.0, expect = ballVolume(1) - lens;
  for (const auto& level : r.json["alphas"]) {
    EXPECT_NEAR(level["lower_volume"].get<double>(), expect, 0.03 * expect) << level.dump();
    EXPECT_NEAR(level["upper_volume"].get<double>(), expect, 0.03 * expect) << level.dump();
  }
  EXPECT_EQ(r.json["nodes"], 3);
}

TEST_F(EvaluateApi, BoundaryMethodAgreesWithTheEnvelopeWhereVolumeIsMonotone) {
  // A fuzzy size: the corner shapes of extreme volume are the envelope's bounds
  // (Zhang, Pham & Chen, eq. 4).
  json request = {{"shape", fuzzyBall(0.8, 1.0, 1.2)}, {"resolution", 64}, {"alphas", {0, 0.5, 1}}};
  auto envelope = server->post("/evaluate", request);
  request["method"] = "boundary";
  auto boundary = server->post("/evaluate", request);
  ASSERT_EQ(boundary.status, 200) << boundary.body;
  EXPECT_EQ(boundary.json["method"], "boundary");
  for (size_t i = 0; i < 3; ++i)
    for (const char* key : {"lower_volume", "upper_volume"}) {
      const double e = envelope.json["alphas"][i][key], b = boundary.json["alphas"][i][key];
      EXPECT_NEAR(b, e, 0.01 * e) << key << " at " << i;
    }
  // A fuzzy translation does not change the volume: the boundary method keeps one ball per
  // level, while the envelope's upper shape is the swept capsule (larger).
  json moving = fuzzyBall(1, 1, 1);
  moving["transform"]["translate"][0] = {{"tri", {-0.5, 0, 0.5}}};
  json req2 = {{"shape", moving}, {"resolution", 64}, {"alphas", {0}}};
  const double envUpper = server->post("/evaluate", req2).json["alphas"][0]["upper_volume"];
  req2["method"] = "boundary";
  const double bndUpper = server->post("/evaluate", req2).json["alphas"][0]["upper_volume"];
  EXPECT_NEAR(bndUpper, ballVolume(1), 0.03 * ballVolume(1));
  EXPECT_NEAR(envUpper, ballVolume(1) + kPi * 1.0, 0.03 * (ballVolume(1) + kPi));  // capsule of length 1
}

TEST_F(EvaluateApi, BadRequestsNameTheirPathAndLimit) {
  auto r = server->post("/evaluate", json{{"shape", fuzzyBall(1, 1, 1)}, {"resolution", 1000}});
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(r.json["error"]["path"], "resolution");
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_resolution=200"), std::string::npos);

  json badEps = fuzzyBall(1, 1, 1);
  badEps["params"]["eps1"] = {{"tri", {0.5, 0.4, 1}}};
  r = server->post("/evaluate", json{{"shape", badEps}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "shape.params.eps1.tri[1]") << r.body;

  json outOfRange = fuzzyBall(1, 1, 1);
  outOfRange["params"]["eps1"] = {{"tri", {1, 2, 5}}};
  r = server->post("/evaluate", json{{"shape", outOfRange}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "shape.params.eps1") << r.body;

  r = server->post("/evaluate", json{{"shape", fuzzyBall(1, 1, 1)}, {"alphas", {0.5, 1.5}}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "alphas[1]");

  r = server->post("/evaluate", json{{"shape", fuzzyBall(1, 1, 1)}, {"method", "corners"}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "method");

  json byName = {{"kind", "shape"}, {"tree", {{"op", "union"}, {"children", {{{"part", "cylinder"}}, {{"part", "cube"}}}}}}};
  r = server->post("/evaluate", json{{"shape", byName}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "shape.tree.children[0].part");

  json tooMany = {{"kind", "shape"}, {"tree", {{"op", "union"}, {"children", json::array()}}}};
  for (int i = 0; i < 6; ++i) tooMany["tree"]["children"].push_back({{"part", fuzzyBall(1, 1, 1, i)}});
  r = server->post("/evaluate", json{{"shape", tooMany}});
  EXPECT_EQ(r.status, 413);
  EXPECT_NE(r.json["error"]["message"].get<std::string>().find("max_nodes=5"), std::string::npos) << r.body;

  json smooth = {{"kind", "shape"},
                 {"tree", {{"op", "union"}, {"operator", {{"name", "einstein"}}},
                           {"children", {{{"part", fuzzyBall(1, 1, 1)}}, {{"part", fuzzyBall(1, 1, 1, 1)}}}}}}};
  r = server->post("/evaluate", json{{"shape", smooth}, {"resolution", 24}, {"alphas", {0.25, 0.5, 0.75, 1}}});
  ASSERT_EQ(r.status, 200) << r.body;  // smooth node operators evaluate (README: Operators at CSG nodes)
  for (const auto& level : r.json["alphas"])  // lower(α) ⊆ upper(α) at every level
    EXPECT_LE(level["lower_volume"].get<double>(), level["upper_volume"].get<double>()) << r.body;
  // Crisp parts only: the blended shape at α = 1, where lower and upper meet.
  const double lower1 = r.json["alphas"][3]["lower_volume"], upper1 = r.json["alphas"][3]["upper_volume"];
  EXPECT_NEAR(lower1, upper1, 0.01 * upper1) << r.body;
  r = server->post("/evaluate", json{{"shape", smooth}, {"method", "boundary"}});
  EXPECT_EQ(r.status, 422);  // the boundary method knows only the zadeh Booleans
  EXPECT_EQ(r.json["error"]["path"], "shape.tree.operator") << r.body;
  smooth["tree"]["range"] = -1;
  r = server->post("/evaluate", json{{"shape", smooth}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "shape.tree.range") << r.body;

  json noSize = {{"kind", "part"}, {"params", {{"eps1", 1}}}};
  r = server->post("/evaluate", json{{"shape", noSize}});
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(r.json["error"]["path"], "shape.params.a1");
  EXPECT_EQ(server->get("/health").status, 200);
}

TEST(EvalCommand, PrintsTheFuzzyVolumeOfAFile) {
  const std::string path = ::testing::TempDir() + "fsdb_eval_ball.json";
  std::ofstream(path) << fuzzyBall(0.9, 1.0, 1.1).dump();
  const std::string cmd = std::string(FSDB_BINARY) + " eval " + path + " --resolution 48 --alphas 0,1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  EXPECT_EQ(pclose(pipe), 0) << out;
  json result = json::parse(out);
  ASSERT_EQ(result["alphas"].size(), 2u);
  EXPECT_NEAR(result["alphas"][1]["upper_volume"].get<double>(), ballVolume(1.0), 0.05 * ballVolume(1.0));
  EXPECT_EQ(std::system((std::string(FSDB_BINARY) + " eval /no/such/file.json 2>/dev/null").c_str()) >> 8, 1);
}

}  // namespace

namespace {

std::string run(const std::string& cmd, int* status) {
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  *status = pclose(pipe);
  return out;
}

TEST(EvalCommand, ExportsAWatertightStlAnObjAndAVdbFileThatVdbPrintReads) {
  const std::string dir = ::testing::TempDir();
  const std::string doc = dir + "fsdb_eval_export.json", stl = dir + "fsdb_export.stl", obj = dir + "fsdb_export.obj",
                    vdb = dir + "fsdb_export.vdb";
  json shape = {{"kind", "shape"},
                {"tree", {{"op", "difference"},
                          {"children", {{{"part", fuzzyBall(0.8, 1.0, 1.2)}}, {{"part", fuzzyBall(0.4, 0.5, 0.6, 0.9)}}}}}}};
  std::ofstream(doc) << shape.dump();
  int status = 0;
  std::string out = run(std::string(FSDB_BINARY) + " eval " + doc + " --resolution 40 --mesh " + stl +
                            " --mesh-alpha 0.5 --mesh-bound lower --vdb " + vdb,
                        &status);
  ASSERT_EQ(status, 0) << out;
  EXPECT_GT(json::parse(out)["mesh"]["triangles"].get<int>(), 100);

  // admesh (Debian package) checks the STL: one part, no open edges, nothing to repair.
  std::string report = run("admesh " + stl + " 2>&1", &status);
  ASSERT_EQ(status, 0) << report;
  for (const char* line : {"Number of parts       :     1", "Degenerate facets     :     0", "Edges fixed           :     0",
                           "Facets removed        :     0", "Facets added          :     0", "Facets reversed       :     0",
                           "Backwards edges       :     0", "Total disconnected facets        :     0                   0"})
    EXPECT_NE(report.find(line), std::string::npos) << line << "\n" << report;

  std::string grids = run("vdb_print " + vdb + " 2>&1", &status);
  ASSERT_EQ(status, 0) << grids;
  EXPECT_NE(grids.find("upper"), std::string::npos) << grids;
  EXPECT_NE(grids.find("lower"), std::string::npos) << grids;

  out = run(std::string(FSDB_BINARY) + " eval " + doc + " --resolution 24 --mesh " + obj + " 2>&1", &status);
  ASSERT_EQ(status, 0) << out;
  std::ifstream objFile(obj);
  std::string first;
  std::getline(objFile, first);
  EXPECT_EQ(first.rfind("# fsdb mesh:", 0), 0u) << first;

  out = run(std::string(FSDB_BINARY) + " eval " + doc + " --mesh " + dir + "x.ply 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(out.find("\"path\":\"--mesh\""), std::string::npos) << out;
}

}  // namespace
