// Parts and shapes over HTTP against the real `fsdb serve --db FILE` (docs/api.md §4): create, read
// any version, list with paging, delete (in_use / cascade), ids never reused, shapes by name, id
// and csg text, /health counts, cached evaluation, membership, exports, and persistence across a
// restart on the same file.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

json ball(const std::string& name, double r, double x = 0) {
  return {{"kind", "part"},
          {"name", name},
          {"params", {{"a1", r}}},
          {"transform", {{"translate", {x, 0, 0}}}}};
}

int64_t createdId(const ServerProcess::Reply& r) {
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json.value("id", int64_t{0});
}

class StoreApi : public ::testing::Test {
 protected:
  TempDir dir;
  ServerProcess server{{"--db", dir.file("store.sqlite")}};
};

TEST_F(StoreApi, CreateReturnsIdVersionOneAndLocation) {
  auto r = server.post("/parts", ball("rod", 1));
  ASSERT_EQ(r.status, 201) << r.body;
  const int64_t id = r.json["id"];
  EXPECT_GT(id, 0);
  EXPECT_EQ(r.json["version"], 1);
  EXPECT_EQ(r.json["kind"], "part");
  EXPECT_EQ(r.json["name"], "rod");
  EXPECT_EQ(r.location, "/parts/" + std::to_string(id));
  auto g = server.get(r.location);
  ASSERT_EQ(g.status, 200) << g.body;
  EXPECT_EQ(g.json["id"], id);
  EXPECT_EQ(g.json["document"]["params"]["a1"], 1);
}

TEST_F(StoreApi, PutAddsAVersionAndOldVersionsStayReadable) {
  const int64_t id = createdId(server.post("/parts", ball("rod", 1)));
  const std::string at = "/parts/" + std::to_string(id);
  auto p = server.put(at, ball("rod", 2));
  ASSERT_EQ(p.status, 200) << p.body;
  EXPECT_EQ(p.json["id"], id);
  EXPECT_EQ(p.json["version"], 2);
  EXPECT_EQ(server.get(at).json["document"]["params"]["a1"], 2);
  auto v1 = server.get(at + "?version=1");
  ASSERT_EQ(v1.status, 200) << v1.body;
  EXPECT_EQ(v1.json["version"], 1);
  EXPECT_EQ(v1.json["latest_version"], 2);
  EXPECT_EQ(v1.json["document"]["params"]["a1"], 1);
  EXPECT_EQ(server.get(at + "?version=3").status, 404);
  // A PUT without a name keeps the object's name.
  json noName = ball("x", 3);
  noName.erase("name");
  auto p3 = server.put(at, noName);
  ASSERT_EQ(p3.status, 200) << p3.body;
  EXPECT_EQ(p3.json["name"], "rod");
  EXPECT_EQ(p3.json["version"], 3);

  auto byName = server.get("/parts?name=rod&version=2");
  ASSERT_EQ(byName.status, 200) << byName.body;
  ASSERT_EQ(byName.json["items"].size(), 1u);
  EXPECT_EQ(byName.json["items"][0]["version"], 2);
  EXPECT_EQ(byName.json["items"][0]["document"]["params"]["a1"], 2);
  auto latest = server.get("/parts?name=rod");
  ASSERT_EQ(latest.json["items"].size(), 1u);
  EXPECT_EQ(latest.json["items"][0]["version"], 3);
  EXPECT_TRUE(server.get("/parts?name=nothing").json["items"].empty());
}

TEST_F(StoreApi, ListPagesWithLimitAndAfter) {
  std::vector<int64_t> ids;
  for (int i = 0; i < 7; ++i) ids.push_back(createdId(server.post("/parts", ball("p" + std::to_string(i), 1))));
  std::vector<int64_t> seen;
  std::string next = "";
  for (int page = 0; page < 10; ++page) {
    auto r = server.get("/parts?limit=3" + (next.empty() ? "" : "&after=" + next));
    ASSERT_EQ(r.status, 200) << r.body;
    EXPECT_LE(r.json["items"].size(), 3u);
    for (const auto& item : r.json["items"]) seen.push_back(item["id"]);
    if (r.json["next_after"].is_null()) break;
    next = std::to_string(r.json["next_after"].get<int64_t>());
  }
  EXPECT_EQ(seen, ids);
  EXPECT_TRUE(server.get("/shapes").json["items"].empty());
}

TEST_F(StoreApi, DeleteThenNotFoundAndIdsAreNeverReused) {
  const int64_t a = createdId(server.post("/parts", ball("a", 1)));
  const int64_t b = createdId(server.post("/parts", ball("b", 1)));
  auto d = server.del("/parts/" + std::to_string(b));
  ASSERT_EQ(d.status, 200) << d.body;
  EXPECT_EQ(d.json["deleted"], json({b}));
  EXPECT_EQ(server.get("/parts/" + std::to_string(b)).status, 404);
  EXPECT_EQ(server.get("/parts/" + std::to_string(b)).json["error"]["code"], "not_found");
  EXPECT_EQ(server.del("/parts/" + std::to_string(b)).status, 404);
  // The name is free again, the id is not.
  const int64_t b2 = createdId(server.post("/parts", ball("b", 1)));
  EXPECT_GT(b2, b);
  EXPECT_NE(b2, a);
  EXPECT_EQ(server.get("/parts/" + std::to_string(b)).status, 404);
}

TEST_F(StoreApi, ShapesReferencePartsByNameIdAndCsgText) {
  const int64_t a = createdId(server.post("/parts", ball("A", 1)));
  createdId(server.post("/parts", ball("B", 1, 1)));
  json byName = {{"kind", "shape"}, {"name", "u1"},
                 {"tree", {{"op", "union"}, {"children", {{{"part", "A"}}, {{"part", "B"}}}}}}};
  auto s1 = server.post("/shapes", byName);
  ASSERT_EQ(s1.status, 201) << s1.body;
  EXPECT_EQ(s1.location, "/shapes/" + std::to_string(s1.json["id"].get<int64_t>()));
  json byId = {{"kind", "shape"}, {"name", "d1"},
               {"tree", {{"op", "difference"}, {"children", {{{"part", a}}, {{"ref", "u1"}}}}}}};
  auto s2 = server.post("/shapes", byId);
  ASSERT_EQ(s2.status, 201) << s2.body;
  auto s3 = server.post("/shapes", json{{"kind", "shape"}, {"name", "C"}, {"csg", "C = A + B * u1"}});
  ASSERT_EQ(s3.status, 201) << s3.body;
  auto g = server.get("/shapes?name=C");
  ASSERT_EQ(g.json["items"].size(), 1u);
  EXPECT_EQ(g.json["items"][0]["document"]["csg"], "C = A + B * u1");
  // A shape is not a part: the kinds have their own routes.
  EXPECT_EQ(server.get("/parts/" + std::to_string(s1.json["id"].get<int64_t>())).status, 404);

  auto h = server.get("/health");
  ASSERT_EQ(h.status, 200);
  EXPECT_EQ(h.json["parts"], 2);
  EXPECT_EQ(h.json["shapes"], 3);
}

TEST_F(StoreApi, DeleteOfAReferencedPartIsInUseUnlessCascade) {
  const int64_t a = createdId(server.post("/parts", ball("A", 1)));
  const int64_t other = createdId(server.post("/parts", ball("other", 1)));
  const int64_t s = createdId(server.post(
      "/shapes", json{{"kind", "shape"}, {"name", "s"}, {"tree", {{"part", "A"}}}}));
  const int64_t t = createdId(server.post(
      "/shapes", json{{"kind", "shape"}, {"name", "t"}, {"tree", {{"ref", "s"}}}}));
  auto refused = server.del("/parts/" + std::to_string(a));
  EXPECT_EQ(refused.status, 409) << refused.body;
  EXPECT_EQ(refused.json["error"]["code"], "in_use");
  EXPECT_EQ(server.get("/parts/" + std::to_string(a)).status, 200);
  auto cascade = server.del("/parts/" + std::to_string(a) + "?cascade=true");
  ASSERT_EQ(cascade.status, 200) << cascade.body;
  std::set<int64_t> deleted;
  for (const auto& id : cascade.json["deleted"]) deleted.insert(id.get<int64_t>());
  EXPECT_EQ(deleted, (std::set<int64_t>{a, s, t}));
  EXPECT_EQ(cascade.json["deleted"][0], a);
  for (int64_t id : {s, t}) EXPECT_EQ(server.get("/shapes/" + std::to_string(id)).status, 404);
  EXPECT_EQ(server.get("/parts/" + std::to_string(other)).status, 200);
  auto h = server.get("/health");
  EXPECT_EQ(h.json["parts"], 1);
  EXPECT_EQ(h.json["shapes"], 0);
}

TEST_F(StoreApi, StoredShapeEvaluationIsCachedUntilAReferencedPartChanges) {
  const int64_t a = createdId(server.post("/parts", ball("A", 1)));
  const int64_t s = createdId(server.post(
      "/shapes", json{{"kind", "shape"}, {"name", "s"}, {"tree", {{"part", "A"}}}}));
  const std::string at = "/shapes/" + std::to_string(s) + "/evaluate";
  const json request = {{"resolution", 24}, {"alphas", {1.0}}};
  auto first = server.post(at, request);
  ASSERT_EQ(first.status, 200) << first.body;
  EXPECT_EQ(first.json["cached"], false);
  auto second = server.post(at, request);
  ASSERT_EQ(second.status, 200) << second.body;
  EXPECT_EQ(second.json["cached"], true);
  EXPECT_EQ(second.json["alphas"], first.json["alphas"]);
  ASSERT_EQ(server.put("/parts/" + std::to_string(a), ball("A", 2)).status, 200);
  auto third = server.post(at, request);
  ASSERT_EQ(third.status, 200) << third.body;
  EXPECT_EQ(third.json["cached"], false);
  const double v1 = first.json["alphas"][0]["upper_volume"], v3 = third.json["alphas"][0]["upper_volume"];
  EXPECT_GT(v3, 6 * v1);  // radius doubled: eight times the volume, up to the grid
  // A change two references down (part A -> shape s -> shape t) invalidates t's cached result too.
  const int64_t t = createdId(server.post("/shapes", json{{"kind", "shape"}, {"name", "t"}, {"tree", {{"ref", "s"}}}}));
  const std::string tAt = "/shapes/" + std::to_string(t) + "/evaluate";
  ASSERT_EQ(server.post(tAt, request).json["cached"], false);
  ASSERT_EQ(server.post(tAt, request).json["cached"], true);
  ASSERT_EQ(server.put("/parts/" + std::to_string(a), ball("A", 1)).status, 200);
  auto t3 = server.post(tAt, request);
  EXPECT_EQ(t3.json["cached"], false) << t3.body;
  EXPECT_EQ(t3.json["alphas"], first.json["alphas"]);
  // An empty body means the defaults.
  auto defaults = server.post(at, std::string(""));
  EXPECT_EQ(defaults.status, 200) << defaults.body;
}

TEST_F(StoreApi, MembershipAndExports) {
  createdId(server.post("/parts", json{{"kind", "part"}, {"name", "fuzzy"}, {"params", {{"a1", {{"tri", {0.8, 1, 1.2}}}}}}}));
  const int64_t s = createdId(server.post(
      "/shapes",
      json{{"kind", "shape"}, {"name", "s"}, {"tree", {{"part", "fuzzy"}}}}));
  const std::string at = "/shapes/" + std::to_string(s);
  auto centre = server.get(at + "/membership?x=0&y=0&z=0");
  ASSERT_EQ(centre.status, 200) << centre.body;
  EXPECT_DOUBLE_EQ(centre.json["upper"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(centre.json["lower"].get<double>(), 1.0);
  auto far = server.get(at + "/membership?x=5&y=0&z=0");
  ASSERT_EQ(far.status, 200) << far.body;
  EXPECT_DOUBLE_EQ(far.json["upper"].get<double>(), 0.0);
  auto edge = server.get(at + "/membership?x=1.1&y=0&z=0");  // inside upper(α) for α ≤ 0.5
  ASSERT_EQ(edge.status, 200) << edge.body;
  EXPECT_NEAR(edge.json["upper"].get<double>(), 0.5, 0.02);
  EXPECT_DOUBLE_EQ(edge.json["lower"].get<double>(), 0.0);

  auto obj = server.get(at + "/mesh?alpha=0.5&bound=upper&format=obj&resolution=24");
  ASSERT_EQ(obj.status, 200) << obj.body.substr(0, 200);
  EXPECT_EQ(obj.contentType, "model/obj");
  EXPECT_NE(obj.body.find("\nf "), std::string::npos);
  EXPECT_EQ(obj.body.rfind("v ", 0) == 0 || obj.body.find("\nv ") != std::string::npos, true);
  auto stl = server.get(at + "/mesh?alpha=0.5&bound=lower&format=stl&resolution=24");
  ASSERT_EQ(stl.status, 200) << stl.body.substr(0, 200);
  EXPECT_EQ(stl.contentType, "model/stl");
  ASSERT_GE(stl.body.size(), 84u);
  uint32_t triangles = 0;
  std::memcpy(&triangles, stl.body.data() + 80, 4);
  EXPECT_GT(triangles, 0u);
  EXPECT_EQ(stl.body.size(), 84u + 50u * triangles);
  // GLB: lower and upper at one α as two named meshes (`bound` does not apply).
  auto glb = server.get(at + "/mesh?alpha=0.5&format=glb&resolution=24");
  ASSERT_EQ(glb.status, 200) << glb.body.substr(0, 200);
  EXPECT_EQ(glb.contentType, "model/gltf-binary");
  ASSERT_GE(glb.body.size(), 20u);
  EXPECT_EQ(glb.body.substr(0, 4), "glTF");
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, glb.body.data() + 12, 4);
  const json gltf = json::parse(glb.body.substr(20, jsonLength));
  ASSERT_EQ(gltf["meshes"].size(), 2u);
  EXPECT_EQ(gltf["meshes"][0]["name"], "lower");
  EXPECT_EQ(gltf["meshes"][1]["name"], "upper");
  // The fuzzy radius: upper(0.5) reaches 1.1, lower(0.5) 0.9 (within a voxel of 2.4 / 24).
  const double upperMax = gltf["accessors"][gltf["meshes"][1]["primitives"][0]["attributes"]["POSITION"].get<size_t>()]["max"][0];
  const double lowerMax = gltf["accessors"][gltf["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<size_t>()]["max"][0];
  EXPECT_GT(upperMax, lowerMax);
  EXPECT_NEAR(upperMax, 1.1, 0.15);
  EXPECT_NEAR(lowerMax, 0.9, 0.15);
  // Thumbnails: a PNG, cached by content; parts have them too.
  auto png = server.get(at + "/thumbnail.png?size=64");
  ASSERT_EQ(png.status, 200) << png.body.substr(0, 200);
  EXPECT_EQ(png.contentType, "image/png");
  EXPECT_EQ(png.body.substr(1, 3), "PNG");
  EXPECT_EQ(server.get(at + "/thumbnail.png?size=64").body, png.body);
  auto partPng = server.get("/parts/" + std::to_string(server.get("/parts").json["items"][0]["id"].get<int64_t>()) +
                            "/thumbnail.png");
  EXPECT_EQ(partPng.status, 200) << partPng.body.substr(0, 200);
  EXPECT_EQ(partPng.contentType, "image/png");
  EXPECT_EQ(server.get(at + "/thumbnail.png?size=8").status, 422);
  EXPECT_EQ(server.get(at + "/thumbnail.png?alpha=-1").status, 422);
  EXPECT_EQ(server.get("/shapes/999999/thumbnail.png").status, 404);
  auto vdb = server.get(at + "/grid.vdb?resolution=24");
  ASSERT_EQ(vdb.status, 200) << vdb.body.substr(0, 200);
  EXPECT_EQ(vdb.contentType, "application/octet-stream");
  ASSERT_GE(vdb.body.size(), 8u);
  EXPECT_EQ(static_cast<unsigned char>(vdb.body[0]), 0x20);  // OpenVDB magic 0x56444220, little endian
  EXPECT_EQ(vdb.body.substr(1, 3), "BDV");
  // Cached exports are byte-identical.
  EXPECT_EQ(server.get(at + "/grid.vdb?resolution=24").body, vdb.body);
}

TEST(StorePersistence, EverythingSurvivesARestartOnTheSameFile) {
  TempDir dir;
  const std::string db = dir.file("persist.sqlite");
  json before;
  {
    ServerProcess server({"--db", db});
    const int64_t a = createdId(server.post("/parts", ball("A", 1)));
    createdId(server.post("/parts", ball("gone", 1)));
    ASSERT_EQ(server.put("/parts/" + std::to_string(a), ball("A", 1.5)).status, 200);
    ASSERT_EQ(server.del("/parts/" + std::to_string(a + 1)).status, 200);
    createdId(server.post("/shapes", json{{"kind", "shape"}, {"name", "s"}, {"csg", "s = A"}}));
    before = {server.get("/parts").json, server.get("/shapes").json, server.get("/health").json,
              server.get("/parts/" + std::to_string(a) + "?version=1").json};
    before[2].erase("uptime_s");
    EXPECT_EQ(server.terminate(), 0);
  }
  ServerProcess again({"--db", db});
  const int64_t a = before[0]["items"][0]["id"];
  json after = {again.get("/parts").json, again.get("/shapes").json, again.get("/health").json,
                again.get("/parts/" + std::to_string(a) + "?version=1").json};
  after[2].erase("uptime_s");
  EXPECT_EQ(after, before);
  EXPECT_EQ(after[0]["items"][0]["version"], 2);
  EXPECT_EQ(after[2]["parts"], 1);
  EXPECT_EQ(after[2]["shapes"], 1);
  // Ids stay unique across the restart, even the deleted one's.
  const int64_t fresh = createdId(again.post("/parts", ball("new", 1)));
  EXPECT_GT(fresh, before[1]["items"][0]["id"].get<int64_t>());
}

}  // namespace
