// GET /parts/{id}/params through the real server: a part's fourteen fuzzy values as the server
// reads them (words resolved, defaults filled in, values in normal form), of any version, and an
// answer the server takes back as a part.
#include <gtest/gtest.h>

#include <string>

#include "tests/server/shared_server.h"

using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

class PartParams : public SharedServerTest<PartParams> {};

TEST_F(PartParams, WordsResolvedDefaultsFilledInNormalForms) {
  auto stored =
      server->post("/parts", json{{"kind", "part"}, {"name", "bent-from-words"}, {"text", "a slightly bent cylinder"}});
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string id = std::to_string(stored.json["id"].get<int64_t>());
  auto r = server->get("/parts/" + id + "/params");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["id"], stored.json["id"]);
  EXPECT_EQ(r.json["version"], 1);
  const json& params = r.json["params"];
  for (const char* name : {"eps1", "eps2", "a1", "a2", "a3", "kx", "ky", "kv", "t"})
    EXPECT_TRUE(params.contains(name)) << name;
  // "slightly bent" is a fuzzy curvature; the untouched taper keeps its crisp default.
  EXPECT_TRUE(params["kv"].is_object()) << params;
  EXPECT_EQ(params["kx"], 0);
  const json& transform = r.json["transform"];
  EXPECT_EQ(transform["translate"].size(), 3u);
  EXPECT_EQ(transform["scale"], 1);
  EXPECT_TRUE(transform["rotate"].contains("deg"));
  // The answer is a part document: stored as a new version, it reads back the same values.
  json next = {{"kind", "part"}, {"params", params}, {"transform", transform}};
  next["params"]["a1"] = json{{"tri", {0.9, 1, 1.1}}};
  auto put = server->put("/parts/" + id, next);
  ASSERT_EQ(put.status, 200) << put.body;
  auto second = server->get("/parts/" + id + "/params");
  EXPECT_EQ(second.json["version"], 2);
  EXPECT_EQ(second.json["params"]["a1"], next["params"]["a1"]);
  // An older version by ?version=.
  auto first = server->get("/parts/" + id + "/params?version=1");
  ASSERT_EQ(first.status, 200) << first.body;
  EXPECT_EQ(first.json["version"], 1);
  EXPECT_EQ(first.json["params"], params);
}

TEST_F(PartParams, Errors) {
  EXPECT_EQ(server->get("/parts/999999/params").status, 404);
  EXPECT_EQ(server->get("/parts/x/params").status, 422);
  auto stored = server->post("/parts", json{{"kind", "part"}, {"name", "crisp-one"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string at = "/parts/" + std::to_string(stored.json["id"].get<int64_t>()) + "/params";
  EXPECT_EQ(server->get(at + "?version=7").status, 404);
  auto bad = server->get(at + "?version=0");
  EXPECT_EQ(bad.status, 422);
  EXPECT_EQ(bad.json["error"]["path"], "version");
}

}  // namespace
