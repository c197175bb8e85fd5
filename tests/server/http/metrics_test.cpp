// GET /metrics (server/http/metrics.h): the Prometheus text format of the counters and the
// gauges, and, through a real server, the series a few requests leave.
#include "server/http/metrics.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace fsdb {
namespace {

bool has(const std::string& text, const std::string& line) {
  return text.find("\n" + line + "\n") != std::string::npos || text.rfind(line + "\n", 0) == 0;
}

TEST(Metrics, CountersHistogramsAndGaugesInTheTextFormat) {
  Metrics m;
  m.observe("GET", "/parts/{id}", 200, 0.003);
  m.observe("GET", "/parts/{id}", 200, 0.2);
  m.observe("GET", "/parts/{id}", 404, 0.0005, "not_found");  // the request and its refusal at once
  m.observe("POST", "/say \"hi\"", 201, 100);  // beyond the last bucket; a label to escape
  m.reject("unauthorized");
  m.reject("unauthorized");
  const std::string text = m.text({{"fsdb_x", "An x.", 2.5}, {"fsdb_y_total", "A y.", 7, "counter"}});
  EXPECT_TRUE(has(text, "# TYPE fsdb_http_requests_total counter")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="GET",route="/parts/{id}",status="200"} 2)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="GET",route="/parts/{id}",status="404"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="POST",route="/say \"hi\"",status="201"} 1)")) << text;
  // Cumulative buckets: 0.0005 <= 0.001; 0.003 <= 0.005; 0.2 <= 0.25.
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="GET",route="/parts/{id}",le="0.001"} 1)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="GET",route="/parts/{id}",le="0.005"} 2)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="GET",route="/parts/{id}",le="0.25"} 3)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="GET",route="/parts/{id}",le="+Inf"} 3)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_count{method="GET",route="/parts/{id}"} 3)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="POST",route="/say \"hi\"",le="60"} 0)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_request_duration_seconds_bucket{method="POST",route="/say \"hi\"",le="+Inf"} 1)"))
      << text;
  EXPECT_TRUE(has(text, R"(fsdb_rejected_requests_total{cause="unauthorized"} 2)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_rejected_requests_total{cause="not_found"} 1)")) << text;
  EXPECT_TRUE(has(text, "# TYPE fsdb_x gauge")) << text;
  EXPECT_TRUE(has(text, "fsdb_x 2.5")) << text;
  EXPECT_TRUE(has(text, "# TYPE fsdb_y_total counter")) << text;
  EXPECT_TRUE(has(text, "fsdb_y_total 7")) << text;
}

TEST(MetricsApi, RequestsRefusalsCacheAndGaugesThroughTheServer) {
  TempDir dir;
  ServerProcess server({"--db", test::storeLocation(dir, "metrics.sqlite"), "--token", "t0k", "--max-memory-mb",
                        "512", "--max-cache-mb", "64"});
  server.setToken("t0k");
  auto created = server.post("/parts", json{{"name", "m"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string at = "/parts/" + std::to_string(created.json["id"].get<int64_t>());
  server.setToken("");
  EXPECT_EQ(server.get(at).status, 200);
  EXPECT_EQ(server.get(at).status, 200);
  EXPECT_EQ(server.get("/parts/999999").status, 404);
  EXPECT_EQ(server.del(at).status, 401);
  EXPECT_EQ(server.get(at + "/mesh?resolution=16").status, 200);
  EXPECT_EQ(server.get("/nowhere").status, 404);
  // A request is counted once its answer is written, which may be after the client has it: ask
  // again until the last one before is there (at most 2 s).
  httplib::Client c = server.client();
  auto r = c.Get("/metrics");
  for (int i = 0; i < 20 && r && r->body.find(R"(route="none",status="404")") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    r = c.Get("/metrics");
  }
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type").rfind("text/plain; version=0.0.4", 0), 0u);
  const std::string text = r->body;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="POST",route="/parts",status="201"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="GET",route="/parts/{id}",status="200"} 2)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="GET",route="/parts/{id}",status="404"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="DELETE",route="/parts/{id}",status="401"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_http_requests_total{method="GET",route="none",status="404"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_rejected_requests_total{cause="unauthorized"} 1)")) << text;
  EXPECT_TRUE(has(text, R"(fsdb_rejected_requests_total{cause="not_found"} 2)")) << text;
  EXPECT_TRUE(has(text, "fsdb_memory_limit_bytes 536870912")) << text;
  EXPECT_TRUE(has(text, "fsdb_memory_reserved_bytes 0")) << text;
  EXPECT_TRUE(has(text, "fsdb_cache_limit_bytes 67108864")) << text;
  EXPECT_TRUE(has(text, "fsdb_cache_entries 1")) << text;  // the mesh
  EXPECT_TRUE(has(text, "fsdb_evaluations_running 0")) << text;
  // This one at least (the one before may still be writing its log line).
  EXPECT_EQ(text.find("fsdb_http_requests_in_flight 0\n"), std::string::npos) << text;
  for (const char* name : {"fsdb_http_connections_queued", "fsdb_http_worker_threads", "fsdb_memory_waiting",
                           "fsdb_memory_refusals_total", "fsdb_cache_bytes", "fsdb_cache_evictions_total",
                           "fsdb_db_pool_connections", "fsdb_db_pool_idle", "fsdb_db_pool_waiting",
                           "fsdb_process_resident_bytes"})
    EXPECT_NE(text.find(std::string("\n# TYPE ") + name + " "), std::string::npos) << name;
}

}  // namespace
}  // namespace fsdb
