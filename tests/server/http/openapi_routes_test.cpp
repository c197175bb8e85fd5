// GET /openapi.json describes exactly the endpoints the server registers: no more, no fewer.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <set>

#include "db/store.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/http/openapi.h"
#include "tests/db/temp_dir.h"

namespace {

TEST(OpenApi, DocumentIsOpenApi3WithInfo) {
  auto doc = nlohmann::json::parse(fsdb::openapiDocumentText());
  EXPECT_EQ(doc["openapi"].get<std::string>().substr(0, 2), "3.");
  EXPECT_TRUE(doc["info"].contains("title"));
  EXPECT_TRUE(doc["info"].contains("version"));
}

TEST(OpenApi, DescribesExactlyTheRegisteredRoutes) {
  fsdb::TempDir dir;
  auto store = fsdb::Store::open(dir.file("routes.sqlite"));
  fsdb::HttpServer server(fsdb::ServerOptions{});
  fsdb::registerAllRoutes(server, *store);
  std::set<std::string> registered, documented;
  for (const auto& r : server.routes()) {
    std::string m = r.method;
    for (auto& c : m) c = static_cast<char>(std::tolower(c));
    EXPECT_TRUE(registered.insert(m + " " + r.openapiPath).second) << "registered twice: " << r.openapiPath;
  }
  auto doc = nlohmann::json::parse(fsdb::openapiDocumentText());
  for (auto& [path, item] : doc["paths"].items())
    for (auto& [method, op] : item.items()) documented.insert(method + " " + path);
  EXPECT_EQ(registered, documented);
}

TEST(OpenApi, EveryLocalReferenceResolves) {
  auto doc = nlohmann::json::parse(fsdb::openapiDocumentText());
  std::vector<std::string> refs;
  std::function<void(const nlohmann::json&)> walk = [&](const nlohmann::json& j) {
    if (j.is_object()) {
      for (auto& [k, v] : j.items()) {
        if (k == "$ref" && v.is_string()) refs.push_back(v);
        walk(v);
      }
    } else if (j.is_array()) {
      for (auto& v : j) walk(v);
    }
  };
  walk(doc);
  ASSERT_FALSE(refs.empty());
  for (const auto& ref : refs) {
    ASSERT_EQ(ref.rfind("#/", 0), 0u) << ref;
    nlohmann::json::json_pointer ptr(ref.substr(1));
    EXPECT_TRUE(doc.contains(ptr)) << "dangling $ref " << ref;
  }
}

}  // namespace
