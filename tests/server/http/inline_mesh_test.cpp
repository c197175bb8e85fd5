// POST /mesh through the real server: the mesh files of an inline document are the bytes GET
// /parts/{id}/mesh gives for the same document stored (GLB, OBJ, STL); references resolve against
// the store; the request's errors; and the limits of the other heavy routes (413 naming
// max_resolution and max_grid_mb, 503 past the memory budget).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/server/shared_server.h"

using fsdb::test::ServerProcess;
using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

class InlineMesh : public SharedServerTest<InlineMesh> {};

const json kFuzzyPart = json::parse(
    R"({"kind":"part","name":"fuzzy-rod","params":{"a1":{"tri":[0.9,1,1.1]},"a3":{"tri":[1.5,2,2.5]},"kv":{"tri":[0,0.1,0.2]}}})");

TEST_F(InlineMesh, AnInlineDocumentsMeshIsTheStoredOnesBytes) {
  auto stored = server->post("/parts", kFuzzyPart);
  ASSERT_EQ(stored.status, 201) << stored.body;
  const std::string at = "/parts/" + std::to_string(stored.json["id"].get<int64_t>());
  struct Case {
    std::string format, bound, contentType;
  };
  for (const Case& c : std::vector<Case>{
           {"glb", "upper", "model/gltf-binary"}, {"obj", "lower", "model/obj"}, {"stl", "upper", "model/stl"}}) {
    auto byId = server->get(at + "/mesh?resolution=16&alpha=0.25&format=" + c.format + "&bound=" + c.bound);
    ASSERT_EQ(byId.status, 200) << byId.body;
    httplib::Client client = server->client();
    const json body = {
        {"shape", kFuzzyPart}, {"resolution", 16}, {"alpha", 0.25}, {"format", c.format}, {"bound", c.bound}};
    auto inlined = client.Post("/mesh", body.dump(), "application/json");
    ASSERT_TRUE(inlined);
    ASSERT_EQ(inlined->status, 200) << inlined->body;
    EXPECT_EQ(inlined->get_header_value("Content-Type"), c.contentType);
    EXPECT_EQ(inlined->body, byId.body) << c.format;
    EXPECT_EQ(inlined->get_header_value("Content-Disposition").rfind("attachment", 0), 0u);
  }
}

TEST_F(InlineMesh, DefaultsAndReferencesToStoredParts) {
  auto stored = server->post("/parts", json{{"kind", "part"}, {"name", "ball-for-a-ref"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(stored.status, 201) << stored.body;
  // A shape whose leaf names the stored part: the default format is OBJ, upper at 0.5.
  const json shape = {{"kind", "shape"}, {"tree", {{"part", "ball-for-a-ref"}}}};
  httplib::Client client = server->client();
  auto r = client.Post("/mesh", json{{"shape", shape}, {"resolution", 12}}.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "model/obj");
  EXPECT_NE(r->body.find("\nf "), std::string::npos);
  EXPECT_NE(r->get_header_value("Content-Disposition").find("mesh-upper-0.5"), std::string::npos);
}

TEST_F(InlineMesh, Errors) {
  const json part = {{"kind", "part"}, {"params", {{"a1", 1}}}};
  struct Case {
    json body;
    int status;
    std::string path;
  };
  const std::vector<Case> cases = {
      {json{{"resolution", 8}}, 422, "shape"},
      {json{{"shape", part}, {"alpha", 1.5}}, 422, "alpha"},
      {json{{"shape", part}, {"format", "ply"}}, 422, "format"},
      {json{{"shape", part}, {"bound", "both"}}, 422, "bound"},
      {json{{"shape", part}, {"resolution", 2.5}}, 422, "resolution"},
      {json{{"shape", part}, {"resolution", "high"}}, 422, "resolution"},
      {json{{"shape", part}, {"resolution", 100000}}, 413, "resolution"},
      {json{{"shape", part}, {"colour", "red"}}, 422, "colour"},
      {json{{"shape", {{"kind", "part"}, {"params", {{"a1", -1}}}}}}, 422, "shape.params.a1"},
      {json{{"shape", {{"kind", "shape"}, {"tree", {{"part", "no-such-part"}}}}}}, 422, "shape.tree.part"},
  };
  for (const Case& c : cases) {
    auto r = server->post("/mesh", c.body);
    EXPECT_EQ(r.status, c.status) << c.body << ": " << r.body;
    EXPECT_EQ(r.json["error"]["path"], c.path) << c.body << ": " << r.body;
  }
  auto malformed = server->client().Post("/mesh", "{\"shape\":", "application/json");
  ASSERT_TRUE(malformed);
  EXPECT_EQ(malformed->status, 400);
  EXPECT_EQ(server->get("/health").status, 200);
}

class InlineMeshGridLimit : public SharedServerTest<InlineMeshGridLimit> {
 public:
  // 1 MiB of grid holds a crisp ball at resolution 32, not at 128 (evaluation_limits_test.cpp).
  static std::vector<std::string> serverArgs() { return {"--max-grid-mb", "1"}; }
};

TEST_F(InlineMeshGridLimit, IsThe413OfTheOtherHeavyRoutes) {
  const json ball = {{"kind", "part"}, {"params", {{"a1", 1}}}};
  EXPECT_EQ(server->post("/mesh", json{{"shape", ball}, {"resolution", 32}}).status, 200);
  auto big = server->post("/mesh", json{{"shape", ball}, {"resolution", 128}});
  EXPECT_EQ(big.status, 413) << big.body;
  EXPECT_EQ(big.json["error"]["path"], "resolution");
  EXPECT_NE(big.body.find("max_grid_mb=1"), std::string::npos) << big.body;
}

// Past --max-memory-mb the answer is 503 overloaded with Retry-After, and nothing stays reserved.
TEST(InlineMeshMemory, PastTheBudgetIs503WithRetryAfter) {
  ServerProcess server({"--max-memory-mb", "1"});
  const json fuzzy = {{"kind", "part"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.1}}}}}}};
  EXPECT_EQ(server.post("/mesh", json{{"shape", fuzzy}, {"resolution", 16}}).status, 200);
  httplib::Client client = server.client();
  auto big = client.Post("/mesh", json{{"shape", fuzzy}, {"resolution", 96}}.dump(), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 503) << big->body;
  EXPECT_EQ(big->get_header_value("Retry-After"), "5");
  EXPECT_EQ(server.post("/mesh", json{{"shape", fuzzy}, {"resolution", 16}}).status, 200);
}

}  // namespace
