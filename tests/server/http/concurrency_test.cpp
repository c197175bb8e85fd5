// Eight clients mixing reads and writes against one `fsdb serve --db FILE` for a few seconds:
// creates, reads, new versions, lists, small evaluations. No 5xx, no transport error, and the
// final counts are what the clients created.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

TEST(Concurrency, EightClientsMixingReadsAndWrites) {
  TempDir dir;
  // 16 workers: at most half of them build grids (RouteOptions::heavy), so eight clients that may
  // all evaluate at once stay within the server's bounds and every answer must succeed.
  ServerProcess server({"--db", dir.file("concurrent.sqlite"), "--threads", "16"});
  constexpr int kThreads = 8;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(4);
  std::atomic<int> parts{0}, shapes{0}, requests{0}, serverErrors{0}, transportErrors{0}, unexpected{0};
  std::vector<std::string> failures(kThreads);

  std::vector<std::thread> clients;
  for (int t = 0; t < kThreads; ++t)
    clients.emplace_back([&, t] {
      httplib::Client c(server.host(), server.port());
      c.set_read_timeout(60, 0);
      auto check = [&](const httplib::Result& r, int want) -> json {
        ++requests;
        if (!r) {
          ++transportErrors;
          failures[t] = httplib::to_string(r.error());
          return nullptr;
        }
        if (r->status >= 500) ++serverErrors;
        if (r->status != want) {
          ++unexpected;
          failures[t] = std::to_string(r->status) + " " + r->body;
          return nullptr;
        }
        return json::parse(r->body, nullptr, false);
      };
      for (int i = 0; std::chrono::steady_clock::now() < deadline; ++i) {
        const std::string name = "t" + std::to_string(t) + "-" + std::to_string(i);
        json p = check(c.Post("/parts", json{{"kind", "part"}, {"name", name}, {"params", {{"a1", 0.5 + i % 3}}}}.dump(),
                              "application/json"),
                       201);
        if (p.is_null()) continue;
        ++parts;
        const std::string at = "/parts/" + std::to_string(p["id"].get<int64_t>());
        check(c.Get(at), 200);
        check(c.Put(at, json{{"kind", "part"}, {"name", name}, {"params", {{"a1", 1.5}}}}.dump(), "application/json"),
              200);
        check(c.Get(at + "?version=1"), 200);
        check(c.Get("/parts?limit=20"), 200);
        if (i % 3 == 0) {
          json s = check(c.Post("/shapes",
                                json{{"kind", "shape"},
                                     {"name", "s-" + name},
                                     {"tree", {{"part", name}}}}
                                    .dump(),
                                "application/json"),
                         201);
          if (s.is_null()) continue;
          ++shapes;
          check(c.Post(("/shapes/" + std::to_string(s["id"].get<int64_t>()) + "/evaluate").c_str(),
                       json{{"resolution", 16}, {"alphas", {0.5, 1}}}.dump(), "application/json"),
                200);
          check(c.Post("/evaluate", json{{"shape", {{"kind", "part"}, {"params", {{"a1", 1}}}}}, {"resolution", 16}}.dump(),
                       "application/json"),
                200);
        }
        check(c.Get("/health"), 200);
      }
    });
  for (auto& c : clients) c.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_TRUE(failures[t].empty()) << "client " << t << ": " << failures[t];
  EXPECT_EQ(serverErrors.load(), 0);
  EXPECT_EQ(transportErrors.load(), 0);
  EXPECT_EQ(unexpected.load(), 0);
  auto health = server.get("/health");
  ASSERT_EQ(health.status, 200);
  EXPECT_EQ(health.json["parts"], parts.load());
  EXPECT_EQ(health.json["shapes"], shapes.load());
  EXPECT_GT(parts.load(), kThreads);
  std::cout << "[concurrency] " << requests.load() << " requests, " << parts.load() << " parts, " << shapes.load()
            << " shapes in 4 s" << std::endl;
}

TEST(Concurrency, ConcurrentPutsOfOneObjectGetDistinctVersions) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("puts.sqlite"), "--threads", "8"});
  auto created = server.post("/parts", json{{"kind", "part"}, {"name", "hot"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string at = "/parts/" + std::to_string(created.json["id"].get<int64_t>());
  constexpr int kThreads = 8, kPuts = 10;
  std::vector<std::vector<int>> versions(kThreads);
  std::vector<std::thread> clients;
  for (int t = 0; t < kThreads; ++t)
    clients.emplace_back([&, t] {
      for (int i = 0; i < kPuts; ++i) {
        auto r = server.put(at, json{{"params", {{"a1", 1 + t + i / 100.0}}}});
        if (r.status == 200) versions[t].push_back(r.json["version"]);
        else ADD_FAILURE() << r.status << " " << r.body;
      }
    });
  for (auto& c : clients) c.join();
  std::set<int> all;
  for (const auto& v : versions) all.insert(v.begin(), v.end());
  EXPECT_EQ(all.size(), static_cast<size_t>(kThreads * kPuts));  // no version handed out twice
  EXPECT_EQ(*all.begin(), 2);
  EXPECT_EQ(*all.rbegin(), 1 + kThreads * kPuts);
  EXPECT_EQ(server.get(at).json["latest_version"], 1 + kThreads * kPuts);
  EXPECT_EQ(server.get(at + "?version=" + std::to_string(kThreads * kPuts)).status, 200);
}

}  // namespace
