// The warm-up of structural search's graphs at serve start (server/service/graph_warmup.h) through the real
// `fsdb serve`: a query sent right after a restart (while the graphs are built in the background)
// answers as a later query does and as a server started with --no-warm-graphs; a server stopped
// during its warm-up exits cleanly.
#include <gtest/gtest.h>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

json words(const std::string& text) { return {{"part", {{"text", text}}}}; }

// The answer without its timing.
json results(const ServerProcess& server, const json& body) {
  auto r = server.post("/query/csg", body);
  EXPECT_EQ(r.status, 200) << r.body;
  json out = r.json;
  out.erase("millis");
  return out;
}

TEST(CsgWarmup, QueryRightAfterStartAnswersAsLaterOnes) {
  TempDir dir;
  const std::string db = dir.file("fsdb.sqlite");
  const std::vector<json> leaves = {words("a very bent cylinder"), words("a very sharp pyramid"), words("a sphere"),
                                    words("a box"), words("a straight cylinder")};
  const std::vector<std::string> ops = {"union", "intersection", "difference"};
  {
    ServerProcess writer({"--db", db});
    for (int i = 0; i < 400; ++i) {
      json tree = {{"op", ops[size_t(i) % 3]}, {"children", {leaves[size_t(i) % 5], leaves[size_t(i / 5) % 5]}}};
      if (i % 4 == 0) tree = {{"op", "union"}, {"children", {tree, leaves[size_t(i / 3) % 5]}}};
      auto r = writer.post("/shapes", json{{"name", "s" + std::to_string(i)}, {"tree", tree}});
      ASSERT_EQ(r.status, 201) << r.body;
    }
    EXPECT_EQ(writer.terminate(), 0);
  }
  const json body = {{"text", "the union of a very bent cylinder and a very sharp pyramid"}, {"limit", 20}};
  json first, later;
  {
    ServerProcess server({"--db", db});
    first = results(server, body);  // during the warm-up, or just after it
    later = results(server, body);
    EXPECT_EQ(results(server, body), later);
  }
  ServerProcess cold({"--db", db, "--no-warm-graphs"});
  const json unwarmed = results(cold, body);
  EXPECT_EQ(first["results"].size(), 20u);
  EXPECT_EQ(first["candidates"], 400);
  EXPECT_EQ(first, later);
  EXPECT_EQ(first, unwarmed);
  EXPECT_EQ(cold.terminate(), 0);
  ServerProcess stopped({"--db", db});
  EXPECT_EQ(stopped.terminate(), 0);  // most likely during its warm-up
}

}  // namespace
