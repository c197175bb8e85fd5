// A shape whose tree names the previous shape twice, 30 levels deep: about 100 bytes a request and
// 2^30 leaves when expanded. Storing each level took time and descriptor rows doubling with the
// depth (16 levels: 65 s and 860 MB), a PUT of the bottom part re-expanded every level, a query
// scored the expansion and an evaluation read the bottom part 2^depth times per voxel. Every
// route now works on the DAG: the whole chain is stored, changed, searched, evaluated, meshed and
// drawn at 30 levels well inside the suite's time (each request in milliseconds here), with the
// answers of the bottom shape.
#include <gtest/gtest.h>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

TEST(ReferenceDag, ThirtyLevelsOfASharedShapeWorkOnTheDag) {
  ServerProcess server;
  ASSERT_EQ(server.post("/parts", json{{"name", "leaf"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.1}}}}}}}).status, 201);
  auto bottom = server.post("/shapes", json{{"name", "s0"},
                                            {"tree",
                                             {{"op", "union"},
                                              {"children",
                                               {{{"part", "leaf"}},
                                                {{"part", {{"params", {{"eps1", 0.1}, {"a1", 0.3}, {"a3", 1.5}}}}},
                                                 {"transform", {{"translate", {0, 2, 0}}}}}}}}}});
  ASSERT_EQ(bottom.status, 201) << bottom.body;
  int64_t top = 0;
  for (int k = 1; k <= 30; ++k) {
    const std::string below = "s" + std::to_string(k - 1);
    auto r = server.post("/shapes", json{{"name", "s" + std::to_string(k)},
                                         {"tree", {{"op", "union"}, {"children", {{{"ref", below}}, {{"ref", below}}}}}}});
    ASSERT_EQ(r.status, 201) << k << " " << r.body;
    top = r.json["id"].get<int64_t>();
  }
  const std::string at = "/shapes/" + std::to_string(top);
  const std::string s0 = "/shapes/" + std::to_string(bottom.json["id"].get<int64_t>());

  // A change of the bottom part refreshes every level's rows.
  auto leafId = server.get("/parts?name=leaf").json["items"][0]["id"].get<int64_t>();
  ASSERT_EQ(server.put("/parts/" + std::to_string(leafId), json{{"name", "leaf"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.2}}}}}}})
                .status,
            200);

  // Searches: the top shape scores as the bottom one, in words and by structure.
  for (const char* text : {"find a rod above a sphere", "a rod on top of a sphere"}) {
    auto found = server.post("/query", json{{"text", text}, {"limit", 100}});
    ASSERT_EQ(found.status, 200) << text << found.body;
    double topScore = -1, bottomScore = -1;
    for (const json& r : found.json["results"]) {
      if (r["name"] == "s30") topScore = r["score"].get<double>();
      if (r["name"] == "s0") bottomScore = r["score"].get<double>();
    }
    EXPECT_GT(bottomScore, 0.0) << text << found.body.substr(0, 600);
    EXPECT_DOUBLE_EQ(topScore, bottomScore) << text;
  }

  // Evaluation, both methods, and the exports: the answers of the bottom shape.
  for (const char* method : {"envelope", "boundary"}) {
    auto a = server.post(at + "/evaluate", json{{"resolution", 24}, {"method", method}});
    auto b = server.post(s0 + "/evaluate", json{{"resolution", 24}, {"method", method}});
    ASSERT_EQ(a.status, 200) << method << a.body;
    ASSERT_EQ(b.status, 200) << method << b.body;
    EXPECT_EQ(a.json["alphas"], b.json["alphas"]) << method;
    EXPECT_EQ(a.json["active_voxels"], b.json["active_voxels"]) << method;
  }
  auto membership = server.get(at + "/membership?x=0&y=0.5&z=0");
  ASSERT_EQ(membership.status, 200) << membership.body;
  EXPECT_EQ(membership.json["upper"], server.get(s0 + "/membership?x=0&y=0.5&z=0").json["upper"]);
  EXPECT_EQ(server.get(at + "/mesh?alpha=0.5&resolution=24&format=stl").status, 200);
  EXPECT_EQ(server.get(at + "/thumbnail.png?size=32").status, 200);
  EXPECT_EQ(server.get(at + "/grid.vdb?resolution=16").status, 200);
  EXPECT_EQ(server.get(at).status, 200);
}

// The same chain joined by a smooth operator (Hamacher) at every level: its bounding box asked the
// children's at every node, the whole expansion (24 levels 1.3 s at 16³, doubling per level; 30
// levels past the 60 s limit). Now every route answers at 30 levels.
TEST(ReferenceDag, ThirtyLevelsOfSmoothUnionsWorkOnTheDag) {
  ServerProcess server;
  ASSERT_EQ(server.post("/parts", json{{"name", "leaf"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.1}}}}}}}).status, 201);
  ASSERT_EQ(server.post("/shapes", json{{"name", "s0"},
                                        {"tree",
                                         {{"op", "union"},
                                          {"children",
                                           {{{"part", "leaf"}},
                                            {{"part", {{"params", {{"eps1", 0.1}, {"a1", 0.3}, {"a3", 1.5}}}}},
                                             {"transform", {{"translate", {0, 2, 0}}}}}}}}}})
                .status,
            201);
  int64_t top = 0;
  for (int k = 1; k <= 30; ++k) {
    const std::string below = "s" + std::to_string(k - 1);
    auto r = server.post("/shapes", json{{"name", "s" + std::to_string(k)},
                                         {"tree",
                                          {{"op", "union"},
                                           {"operator", {{"name", "hamacher"}}},
                                           {"children", {{{"ref", below}}, {{"ref", below}}}}}}});
    ASSERT_EQ(r.status, 201) << k << " " << r.body;
    top = r.json["id"].get<int64_t>();
  }
  const std::string at = "/shapes/" + std::to_string(top);
  auto evaluated = server.post(at + "/evaluate", json{{"resolution", 16}});
  ASSERT_EQ(evaluated.status, 200) << evaluated.body;
  EXPECT_GT(evaluated.json["active_voxels"].get<int64_t>(), 0);
  EXPECT_EQ(server.get(at + "/membership?x=0&y=0.5&z=0").status, 200);
  EXPECT_EQ(server.get(at + "/mesh?alpha=0.5&resolution=24&format=glb").status, 200);
  EXPECT_EQ(server.get(at + "/thumbnail.png?size=32").status, 200);
}

}  // namespace
