// POST /query/linguistic (SPEC §4, issue 5): server/linguistic_search.h does the work.
#include "server/api.h"
#include "server/http_server.h"
#include "server/linguistic_search.h"

namespace fsdb {

void registerQueryRoutes(HttpServer& server, const Store& store) {
  const LinguisticRequestLimits limits{server.options().limits.maxNodes,
                                       static_cast<double>(server.options().limits.maxQueryMs)};
  server.addRoute("POST", "/query/linguistic", [&store, limits](const ApiRequest& req) {
    return ApiResponse{200, linguisticQueryResponse(store, req.body, limits)};
  });
}

}  // namespace fsdb
