// GET /health and GET /openapi.json.
#include <chrono>

#include "db/store.h"
#include "fsdb_version.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/http/openapi.h"

namespace fsdb {

void registerServiceRoutes(HttpServer& server, const Store& store) {
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
}

void registerAllRoutes(HttpServer& server, Store& store) {
  registerServiceRoutes(server, store);
  registerOperatorRoutes(server);
  registerVocabularyRoutes(server);
  registerObjectRoutes(server, store);
  registerEvaluationRoutes(server, store);
  registerBezierRoutes(server, store);
  registerQueryRoutes(server, store);
  registerFairCurveRoutes(server, store);
}

}  // namespace fsdb
