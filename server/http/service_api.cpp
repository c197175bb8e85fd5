// GET /health, GET /openapi.json and GET /metrics.
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <vector>

#include "db/store.h"
#include "fsdb_version.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/http/openapi.h"
#include "server/service/evaluation.h"
#include "server/service/memory_budget.h"

namespace fsdb {

namespace {

// The resident set of this process (/proc/self/statm), 0 where it cannot be read.
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

}  // namespace

void registerServiceRoutes(HttpServer& server, const Store& store, const MemoryBudget& memory) {
  const auto started = std::chrono::steady_clock::now();
  server.addRoute("GET", "/health", [started, &store](const ApiRequest&) {
    const double uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const auto counts = store.counts();
    auto count = [&counts](const char* kind) {
      auto it = counts.find(kind);
      return it == counts.end() ? int64_t{0} : it->second;
    };
    return ApiResponse{200,
                       {{"status", "ok"},
                        {"version", FSDB_VERSION},
                        {"uptime_s", uptime},
                        {"parts", count("part")},
                        {"shapes", count("shape")},
                        {"curves", count("curve")},
                        {"surfaces", count("surface")},
                        {"schema_version", store.schemaVersion()},
                        {"backend", store.backend()}}};
  });
  // Parsed once: the document is constant for the life of the binary.
  static const nlohmann::json openapi = nlohmann::json::parse(openapiDocumentText());
  server.addRoute("GET", "/openapi.json", [](const ApiRequest&) { return ApiResponse{200, openapi}; });

  // Prometheus text format; every metric is listed in docs/api.md §4.
  const std::uint64_t cacheLimit = server.options().maxCacheMb << 20;
  server.addRoute("GET", "/metrics", [&server, &store, &memory, cacheLimit](const ApiRequest&) {
    const StoreStats db = store.stats();
    const std::vector<MetricGauge> gauges = {
        {"fsdb_http_requests_in_flight", "Requests between their request line and their answer.",
         static_cast<double>(server.requestsInFlight())},
        {"fsdb_http_connections_queued", "Requests read whole and waiting for a worker thread.",
         static_cast<double>(server.connectionsQueued())},
        {"fsdb_http_connections_open", "Open client connections: idle, arriving, or with a worker.",
         static_cast<double>(server.connectionsOpen())},
        {"fsdb_http_worker_threads", "Worker threads (--threads).", static_cast<double>(server.workerThreads())},
        {"fsdb_evaluations_running", "Grid builds and smooth meshes running now.",
         static_cast<double>(evaluationsRunning())},
        {"fsdb_memory_reserved_bytes", "Memory reserved by running evaluations and meshes (--max-memory-mb).",
         static_cast<double>(memory.reserved())},
        {"fsdb_memory_limit_bytes", "The memory budget (--max-memory-mb; 0: none).",
         static_cast<double>(memory.limit())},
        {"fsdb_memory_waiting", "Evaluations waiting for a younger one to give its memory back.",
         static_cast<double>(memory.waiting())},
        {"fsdb_memory_refusals_total", "Reservations refused (answered 503 overloaded).",
         static_cast<double>(memory.refusals()), "counter"},
        {"fsdb_cache_bytes", "Bytes of cached evaluations and exports in the database.",
         static_cast<double>(db.cacheBytes)},
        {"fsdb_cache_entries", "Cached evaluations and exports in the database.", static_cast<double>(db.cacheEntries)},
        {"fsdb_cache_limit_bytes", "The cache's bound (--max-cache-mb; 0: none).", static_cast<double>(cacheLimit)},
        {"fsdb_cache_evictions_total", "Cache entries this process evicted to stay within its bound.",
         static_cast<double>(db.cacheEvictions), "counter"},
        {"fsdb_db_pool_connections", "Database connections in the pool.", static_cast<double>(db.poolConnections)},
        {"fsdb_db_pool_idle", "Pooled connections not lent to a call.", static_cast<double>(db.poolIdle)},
        {"fsdb_db_pool_waiting", "Calls waiting for a pooled connection.", static_cast<double>(db.poolWaiting)},
        {"fsdb_process_resident_bytes", "Resident memory of the server process.", residentBytes()},
    };
    ApiResponse out{200, nullptr, server.metrics().text(gauges), "text/plain; version=0.0.4; charset=utf-8"};
    out.headers.emplace_back("Cache-Control", "no-store");
    return out;
  });
}

void registerAllRoutes(HttpServer& server, Store& store) {
  // One memory budget for every evaluation and mesh of this server (--max-memory-mb). Kept for
  // the process's life: a grid a background task still holds gives its reservation back to it
  // even after the server has stopped.
  static std::vector<std::unique_ptr<MemoryBudget>> budgets;
  budgets.push_back(std::make_unique<MemoryBudget>(server.options().limits.maxMemoryMb << 20));
  registerServiceRoutes(server, store, *budgets.back());
  registerOperatorRoutes(server);
  registerVocabularyRoutes(server);
  registerObjectRoutes(server, store);
  registerEvaluationRoutes(server, store, budgets.back().get());
  registerBezierRoutes(server, store);
  registerQueryRoutes(server, store);
  registerFairCurveRoutes(server, store);
}

}  // namespace fsdb
