// GET /vocabulary: the active vocabulary document (schema/vocabulary.json as compiled in, or the
// file of `fsdb serve --vocabulary FILE`), docs/api.md §4.
#include "query/linguistic/vocabulary.h"
#include "server/http/api.h"
#include "server/http/http_server.h"

namespace fsdb {

void registerVocabularyRoutes(HttpServer& server) {
  server.addRoute("GET", "/vocabulary", [](const ApiRequest&) { return ApiResponse{200, activeVocabulary().document()}; });
}

}  // namespace fsdb
