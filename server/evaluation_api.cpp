// POST /evaluate: a shape or part document evaluated on a voxel grid (SPEC §3, §4).
#include "server/api.h"
#include "server/evaluation.h"
#include "server/http_server.h"

namespace fsdb {

void registerEvaluationRoutes(HttpServer& server) {
  const EvaluationLimits limits{server.options().limits.maxResolution, server.options().limits.maxNodes};
  server.addRoute("POST", "/evaluate",
                  [limits](const ApiRequest& req) { return ApiResponse{200, evaluateRequest(req.body, limits), {}, {}}; });
}

}  // namespace fsdb
