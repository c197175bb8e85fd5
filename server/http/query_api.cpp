// POST /query, POST /query/linguistic and POST /query/csg (docs/api.md §4):
// server/service/query_search.h, linguistic_search.h and csg_search.h do the work.
#include <memory>

#include "server/http/api.h"
#include "server/service/csg_search.h"
#include "server/service/graph_warmup.h"
#include "server/http/http_server.h"
#include "server/service/linguistic_search.h"
#include "server/service/query_search.h"

namespace fsdb {

void registerQueryRoutes(HttpServer& server, const Store& store) {
  const LinguisticRequestLimits limits{server.options().limits.maxNodes,
                                       static_cast<double>(server.options().limits.maxQueryMs)};
  server.addRoute("POST", "/query/linguistic", [&store, limits](const ApiRequest& req) {
    return ApiResponse{200, linguisticQueryResponse(store, req.body, limits)};
  });
  const CsgRequestLimits csgLimits{limits.maxNodes, limits.maxQueryMs, server.options().limits.maxCsgPairs};
  // The stored graphs live as long as the route; entries are checked against the store's versions
  // on every query (server/service/stored_graphs.h), so writes need not notify it.
  auto cache = std::make_shared<StoredGraphCache>();
  // Built in the background from the start (server/service/graph_warmup.h); the route owns it, so it stops
  // and joins when the server goes, before the store.
  std::shared_ptr<GraphWarmup> warmup;
  if (server.options().warmGraphs) warmup = std::make_shared<GraphWarmup>(store, cache, limits.maxNodes);
  server.addRoute("POST", "/query/csg", [&store, csgLimits, cache, warmup](const ApiRequest& req) {
    return ApiResponse{200, csgQueryResponse(store, req.body, csgLimits, *cache)};
  });
  // One search box: the text decides which search runs (the same graph cache as /query/csg).
  server.addRoute("POST", "/query", [&store, limits, csgLimits, cache, warmup](const ApiRequest& req) {
    return ApiResponse{200, queryResponse(store, req.body, limits, csgLimits, *cache)};
  });
}

}  // namespace fsdb
