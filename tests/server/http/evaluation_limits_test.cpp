// The evaluation limits of `fsdb serve` and `fsdb eval` against the real binary: --max-grid-mb
// and --max-eval-ms answer 413 naming the limit (inline and stored-shape forms, nothing cached),
// the server keeps serving; "exhausted_searches" counts the fuzzy parts' exhausted searches.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "query/document/part_json.h"
#include "tests/server/shared_server.h"
#include "tests/testing/fuzzy_bench_part.h"
#include "tests/testing/sanitizer_slowdown.h"

using fsdb::test::ServerProcess;
using fsdb::test::SharedServerTest;
using nlohmann::json;

namespace {

json crispBall() { return {{"kind", "part"}, {"params", {{"a1", 1}}}}; }
// All fourteen values fuzzy: the slow part (0.3 s at resolution 20 with 5 exhausted searches, 0.8 s
// at 32, seconds at 64; one core of the shared build machine).
json slowPart() { return fsdb::partToJson(fsdb::testing::allValuesFuzzyPart()); }

void expectLimit(const ServerProcess::Reply& r, const std::string& limit) {
  EXPECT_EQ(r.status, 413) << r.body;
  EXPECT_EQ(r.json["error"]["code"], "limit_exceeded") << r.body;
  EXPECT_EQ(r.json["error"]["path"], "resolution") << r.body;
  const std::string message = r.json["error"]["message"].is_string() ? r.json["error"]["message"].get<std::string>() : "";
  EXPECT_NE(message.find(limit), std::string::npos) << r.body;
  EXPECT_NE(message.find("lower the resolution"), std::string::npos) << r.body;
}

int64_t storeShape(const ServerProcess& server, const std::string& name, const json& part) {
  auto r = server.post("/shapes", json{{"kind", "shape"}, {"name", name}, {"tree", {{"part", part}}}});
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json.value("id", int64_t{0});
}

class TightLimits : public SharedServerTest<TightLimits> {
 public:
  // 1 MiB holds about 250 leaf pairs: a crisp ball at resolution 32, not at 128.
  static std::vector<std::string> serverArgs() { return {"--max-grid-mb", "1", "--max-eval-ms", "300"}; }
};

TEST_F(TightLimits, GridMemoryLimitIs413NamingMaxGridMb) {
  auto ok = server->post("/evaluate", json{{"shape", crispBall()}, {"resolution", 32}});
  ASSERT_EQ(ok.status, 200) << ok.body;
  expectLimit(server->post("/evaluate", json{{"shape", crispBall()}, {"resolution", 128}}), "max_grid_mb=1");
  EXPECT_EQ(server->get("/health").status, 200);
}

TEST_F(TightLimits, StoredShapeFormsAnswerTheSameAndCacheNothing) {
  const std::string at = "/shapes/" + std::to_string(storeShape(*server, "big-ball", crispBall()));
  expectLimit(server->post(at + "/evaluate", json{{"resolution", 128}}), "max_grid_mb=1");
  expectLimit(server->post(at + "/evaluate", json{{"resolution", 128}}), "max_grid_mb=1");  // not cached
  expectLimit(server->get(at + "/mesh?resolution=128"), "max_grid_mb=1");
  expectLimit(server->get(at + "/grid.vdb?resolution=128"), "max_grid_mb=1");
  auto small = server->post(at + "/evaluate", json{{"resolution", 32}});
  ASSERT_EQ(small.status, 200) << small.body;
  EXPECT_EQ(small.json["cached"], false);
  EXPECT_EQ(server->get("/health").status, 200);
}

TEST_F(TightLimits, EvaluationTimeLimitIs413NamingMaxEvalMs) {
  const auto start = std::chrono::steady_clock::now();
  auto r = server->post("/evaluate", json{{"shape", slowPart()}, {"resolution", 64}});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expectLimit(r, "max_eval_ms=300");
  EXPECT_LT(seconds, 1.5 * fsdb::testing::kSlowdown);  // the build stops within a search of the deadline (BlockLattice::checkpoint)
  EXPECT_EQ(server->get("/health").status, 200);
  const std::string at = "/shapes/" + std::to_string(storeShape(*server, "slow", slowPart()));
  expectLimit(server->post(at + "/evaluate", json{{"resolution", 64}}), "max_eval_ms=300");
}

class DefaultLimits : public SharedServerTest<DefaultLimits> {};

TEST_F(DefaultLimits, ExhaustedSearchesAreZeroForACrispPart) {
  auto r = server->post("/evaluate", json{{"shape", crispBall()}, {"resolution", 48}});
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["exhausted_searches"], 0);
}

TEST_F(DefaultLimits, ExhaustedSearchesCountThisEvaluationAndStayWithTheCachedAnswer) {
  const json request = {{"shape", slowPart()}, {"resolution", 20}, {"alphas", {0.5}}};
  auto first = server->post("/evaluate", request);
  ASSERT_EQ(first.status, 200) << first.body;
  ASSERT_TRUE(first.json["exhausted_searches"].is_number_unsigned()) << first.body;
  EXPECT_GT(first.json["exhausted_searches"].get<std::uint64_t>(), 0u);
  // A fresh field per request: the same request counts the same searches again, not their sum.
  auto again = server->post("/evaluate", request);
  EXPECT_EQ(again.json["exhausted_searches"], first.json["exhausted_searches"]);

  const std::string at = "/shapes/" + std::to_string(storeShape(*server, "fuzzy", slowPart())) + "/evaluate";
  auto miss = server->post(at, json{{"resolution", 20}, {"alphas", {0.5}}});
  ASSERT_EQ(miss.status, 200) << miss.body;
  EXPECT_EQ(miss.json["cached"], false);
  EXPECT_EQ(miss.json["exhausted_searches"], first.json["exhausted_searches"]);
  auto hit = server->post(at, json{{"resolution", 20}, {"alphas", {0.5}}});
  EXPECT_EQ(hit.json["cached"], true);
  EXPECT_EQ(hit.json["exhausted_searches"], first.json["exhausted_searches"]);
}

TEST(EvalCommandLimits, FlagsDefaultToNoLimitAndStopWhenGiven) {
  const std::string path = ::testing::TempDir() + "fsdb_eval_limits_ball.json";
  std::ofstream(path) << crispBall().dump();
  auto free = fsdb::test::runFsdb({"eval", path, "--resolution", "128"});
  ASSERT_EQ(free.exitCode, 0) << free.out;
  EXPECT_EQ(json::parse(free.out)["exhausted_searches"], 0);
  auto tight = fsdb::test::runFsdb({"eval", path, "--resolution", "128", "--max-grid-mb", "1"}, true);
  EXPECT_EQ(tight.exitCode, 1);
  const json error = json::parse(tight.out, nullptr, false);
  EXPECT_EQ(error["error"]["code"], "limit_exceeded") << tight.out;
  EXPECT_NE(tight.out.find("max_grid_mb=1"), std::string::npos) << tight.out;
  const std::string slow = ::testing::TempDir() + "fsdb_eval_limits_slow.json";
  std::ofstream(slow) << slowPart().dump();
  auto late = fsdb::test::runFsdb({"eval", slow, "--resolution", "32", "--max-eval-ms", "50"}, true);
  EXPECT_EQ(late.exitCode, 1);
  EXPECT_NE(late.out.find("max_eval_ms=50"), std::string::npos) << late.out;
}

}  // namespace

// Anonymous GETs filled the disk: every new alpha (0.400001, 0.400002, ...) cached a new mesh
// for ever. With --max-cache-mb 1 the cached entries stay within 1 MiB (least recently used
// out first) while every request is still answered, and the latest is still a hit.
namespace {
TEST(CacheBound, NewAlphasDoNotGrowTheCachePastMaxCacheMb) {
  fsdb::test::TempDir dir;
  const std::string db = fsdb::test::storeLocation(dir, "cache.sqlite");
  ServerProcess server({"--db", db, "--max-cache-mb", "1"});
  auto created = server.post("/parts", json{{"name", "ball"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.1}}}}}}});
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string mesh = "/parts/" + std::to_string(created.json["id"].get<int64_t>()) + "/mesh?resolution=32&alpha=";
  size_t served = 0;
  std::string last;
  for (int i = 1; i <= 24; ++i) {
    last = mesh + "0.40000" + std::to_string(i);
    auto r = server.get(last);
    ASSERT_EQ(r.status, 200) << r.body.substr(0, 200);
    served += r.body.size();
  }
  ASSERT_GT(served, 2u << 20) << "the meshes must pass the bound for the test to mean anything";
  httplib::Client c = server.client();
  auto again = c.Get(last.c_str());
  ASSERT_TRUE(again);
  EXPECT_EQ(again->get_header_value("X-Fsdb-Cache"), "hit");
  // The cache's rows, read through the store's own connection type: the sum of their sizes.
  std::unique_ptr<fsdb::sql::Connection> connection;
  if (db.rfind("postgresql://", 0) == 0)
    connection = std::make_unique<fsdb::postgres::Connection>(fsdb::postgres::parseAddress(db));
  else
    connection = std::make_unique<fsdb::sqlite::Connection>(db);
  auto total = connection->prepare("SELECT COALESCE(SUM(bytes), 0), COUNT(*) FROM eval_cache");
  ASSERT_TRUE(total->step());
  EXPECT_LE(total->columnInt(0), 1 << 20);
  EXPECT_GT(total->columnInt(1), 0);
}
}  // namespace

// --max-memory-mb: evaluations and meshes reserve their memory before they allocate it; past the
// budget the answer is 503 overloaded with Retry-After (16 evaluations at 512 at once reached
// 8.2 GB and were still rising), while a request that fits is answered.
namespace {
TEST(MemoryBound, PastTheBudgetIs503WithRetryAfter) {
  ServerProcess server({"--max-memory-mb", "1"});
  const json sphere = {{"kind", "part"}, {"params", {{"a1", {{"tri", {0.9, 1, 1.1}}}}}}};
  auto small = server.post("/evaluate", json{{"shape", sphere}, {"resolution", 16}});
  EXPECT_EQ(small.status, 200) << small.body;
  httplib::Client c = server.client();
  auto big = c.Post("/evaluate", json{{"shape", sphere}, {"resolution", 96}}.dump(), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 503) << big->body;
  EXPECT_EQ(big->get_header_value("Retry-After"), "5");
  const json error = json::parse(big->body)["error"];
  EXPECT_EQ(error["code"], "overloaded");
  EXPECT_NE(error["message"].get<std::string>().find("max_memory_mb=1"), std::string::npos) << big->body;
  // Nothing stays reserved: the small one is answered again.
  EXPECT_EQ(server.post("/evaluate", json{{"shape", sphere}, {"resolution", 16}}).status, 200);
  EXPECT_EQ(server.get("/health").status, 200);
}
}  // namespace

// Grid builds and meshes take at most half the workers: with --threads 4, a third evaluation
// sent while two run is 503 overloaded with Retry-After at once, and /health is answered
// meanwhile (16 evaluations at once held all 16 workers and /health waited 10 s).
namespace {
TEST(HeavyRoutes, AtMostHalfTheWorkersBuildGrids) {
  ServerProcess server({"--threads", "4", "--max-eval-ms", "0"});
  // Long enough that the third request finds both running (about 1 s in Release); smaller under
  // the sanitizers, where it is 20 times slower and would hold both cores for a minute.
  const int resolution = fsdb::testing::kSanitizerBuild ? 16 : 32;
  const std::string body = json{{"shape", slowPart()}, {"resolution", resolution}}.dump();
  std::vector<std::thread> clients;
  std::vector<int> statuses(3, 0);
  std::vector<std::string> retry(3);
  for (int i = 0; i < 3; ++i)
    clients.emplace_back([&, i] {
      std::this_thread::sleep_for(std::chrono::milliseconds(i == 2 ? 300 : 0));  // the third comes last
      httplib::Client c = server.client();
      auto r = c.Post("/evaluate", body, "application/json");
      if (r) {
        statuses[i] = r->status;
        retry[i] = r->get_header_value("Retry-After");
      }
    });
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  const auto t = std::chrono::steady_clock::now();
  EXPECT_EQ(server.get("/health").status, 200);
  EXPECT_LT(std::chrono::steady_clock::now() - t, std::chrono::seconds(5));
  for (auto& c : clients) c.join();
  EXPECT_EQ(statuses[0], 200);
  EXPECT_EQ(statuses[1], 200);
  EXPECT_EQ(statuses[2], 503);
  EXPECT_EQ(retry[2], "5");
}
}  // namespace
