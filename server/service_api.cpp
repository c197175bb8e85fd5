// GET /health and GET /openapi.json.
#include <chrono>

#include "fsdb_version.h"
#include "server/api.h"
#include "server/http_server.h"
#include "server/openapi.h"

namespace fsdb {

void registerServiceRoutes(HttpServer& server) {
  const auto started = std::chrono::steady_clock::now();
  server.addRoute("GET", "/health", [started](const ApiRequest&) {
    const double uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return ApiResponse{200, {{"status", "ok"}, {"version", FSDB_VERSION}, {"uptime_s", uptime}}, {}, {}};
  });
  // Parsed once: the document is constant for the life of the binary.
  static const nlohmann::json openapi = nlohmann::json::parse(openapiDocumentText());
  server.addRoute("GET", "/openapi.json", [](const ApiRequest&) { return ApiResponse{200, openapi, {}, {}}; });
}

void registerAllRoutes(HttpServer& server) {
  registerServiceRoutes(server);
  registerOperatorRoutes(server);
  registerEvaluationRoutes(server);
}

}  // namespace fsdb
