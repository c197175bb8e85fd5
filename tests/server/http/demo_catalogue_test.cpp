// The demo catalogue (schema/demo/*.jsonl, `make serve`): a server started with --demo on a
// fresh database stores every line of every file, and the curves, the surface and the fair
// curves of the catalogue export and answer like any stored object.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

const std::string kDemo = std::string(FSDB_SOURCE_DIR) + "/schema/demo";

// The demo documents by kind, read from the files.
std::map<std::string, std::vector<json>> demoDocuments() {
  std::map<std::string, std::vector<json>> out;
  for (const auto& entry : std::filesystem::directory_iterator(kDemo)) {
    if (entry.path().extension() != ".jsonl") continue;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) {
        const json doc = json::parse(line);
        out[doc.value("kind", "part")].push_back(doc);
      }
  }
  return out;
}

int64_t idOf(const ServerProcess& server, const std::string& kind, const std::string& name) {
  auto r = server.get("/" + kind + "s?name=" + name);
  EXPECT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["items"].size(), 1u) << kind << " " << name;
  return r.json["items"].empty() ? 0 : r.json["items"][0]["id"].get<int64_t>();
}

TEST(DemoCatalogue, EveryLineIsStored) {
  ServerProcess server({"--demo", kDemo});
  const auto docs = demoDocuments();
  const json health = server.get("/health").json;
  for (const auto& [kind, list] : docs) {
    EXPECT_EQ(health[kind + "s"], list.size()) << kind << ": " << health.dump();
    for (const json& doc : list) {
      const int64_t id = idOf(server, kind, doc["name"]);
      EXPECT_EQ(server.get("/" + kind + "s/" + std::to_string(id)).json["document"], doc);
    }
  }
  // The catalogue shows each curve form and a surface.
  ASSERT_GE(docs.count("curve"), 1u);
  ASSERT_GE(docs.count("surface"), 1u);
}

TEST(DemoCatalogue, CurvesAndSurfacesExport) {
  ServerProcess server({"--demo", kDemo});
  const auto docs = demoDocuments();
  bool bezier = false, fair = false;
  for (const json& doc : docs.at("curve")) {
    const std::string base = "/curves/" + std::to_string(idOf(server, "curve", doc["name"]));
    auto svg = server.get(base + "/svg");
    EXPECT_EQ(svg.status, 200) << doc["name"] << svg.body;
    EXPECT_EQ(svg.contentType, "image/svg+xml");
    if (doc.contains("fair")) {
      fair = true;
      auto c = server.get(base + "/candidates");
      ASSERT_EQ(c.status, 200) << c.body;
      EXPECT_GE(c.json["candidates"].size(), 1u);
    } else {
      bezier = true;
      EXPECT_NE(svg.body.find("id=\"crisp\""), std::string::npos);
    }
  }
  EXPECT_TRUE(bezier);
  EXPECT_TRUE(fair);
  // Bernardes, Wu & D'Ottaviano, Figure 7 gives several ranked candidates.
  auto fig7 = server.get("/curves/" + std::to_string(idOf(server, "curve", "fair-figure-7")) + "/candidates");
  EXPECT_GE(fig7.json["candidates"].size(), 2u) << fig7.body;
  for (const json& doc : docs.at("surface")) {
    auto mesh = server.get("/surfaces/" + std::to_string(idOf(server, "surface", doc["name"])) + "/mesh?resolution=4");
    EXPECT_EQ(mesh.status, 200) << mesh.body;
    EXPECT_EQ(mesh.contentType, "model/obj");
  }
}

}  // namespace
