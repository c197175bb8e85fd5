// The studio's server side: `fsdb serve --warm-thumbnails` draws every stored object's thumbnail
// in the background (a later request is a cache hit), and parts answer membership like shapes.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "db/sqlite.h"
#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace {

const std::string kCatalogue = std::string(FSDB_SOURCE_DIR) + "/tests/server/http/designers_catalogue";

TEST(ThumbnailApi, WarmThumbnailsAreDrawnInTheBackground) {
  fsdb::test::TempDir dir;
  const std::string db = dir.file("db.sqlite");
  ServerProcess server({"--db", db, "--demo", kCatalogue, "--warm-thumbnails"});
  // Polled in the database (no request of ours draws one): a cached thumbnail per stored object.
  const auto cachedThumbnails = [&] {
    fsdb::sqlite::Connection c(db);
    auto count = c.prepare("SELECT COUNT(*) FROM eval_cache WHERE key LIKE 'thumbnail:%'");
    return count->step() ? count->columnInt(0) : -1;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  int cached = 0;
  while ((cached = cachedThumbnails()) < 32 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(cached, 32);  // 15 parts and 17 shapes
  // And the server serves them from the cache.
  httplib::Client c = server.client();
  for (const char* kind : {"shapes", "parts"}) {
    const json items = server.get(std::string("/") + kind + "?limit=1000").json["items"];
    for (const json& o : items) {
      const std::string path = std::string("/") + kind + "/" + std::to_string(o["id"].get<int64_t>()) + "/thumbnail.png";
      auto r = c.Get(path.c_str());
      ASSERT_TRUE(r);
      EXPECT_EQ(r->status, 200) << path;
      EXPECT_EQ(r->get_header_value("X-Fsdb-Cache"), "hit") << path;
    }
  }
}

TEST(ThumbnailApi, PartsAnswerMembership) {
  ServerProcess server({"--demo", kCatalogue});
  const json parts = server.get("/parts?name=ball").json["items"];
  ASSERT_EQ(parts.size(), 1u);
  const std::string at = "/parts/" + std::to_string(parts[0]["id"].get<int64_t>()) + "/membership";
  auto inside = server.get(at + "?x=0&y=0&z=0");
  ASSERT_EQ(inside.status, 200) << inside.body;
  EXPECT_EQ(inside.json["upper"], 1.0);
  EXPECT_EQ(inside.json["lower_from"], 0.0);
  auto outside = server.get(at + "?x=3&y=0&z=0");
  EXPECT_EQ(outside.json["upper"], 0.0);
  EXPECT_TRUE(outside.json["lower_from"].is_null());
}

}  // namespace
