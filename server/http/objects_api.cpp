// Parts, shapes, curves and surfaces (docs/api.md §4, §6): create, read (any version), list, new
// versions, delete, bulk. One set of handlers serves every kind; the route's kind is checked against the document's.
#include <algorithm>

#include "geometry/core/error.h"
#include "server/http/api.h"
#include "server/service/bulk_import.h"
#include "server/service/descriptor_rows.h"
#include "server/service/documents.h"
#include "server/http/http_server.h"

namespace fsdb {

int64_t positiveInteger(const std::string& text, const std::string& what, int64_t max) {
  int64_t v = 0;
  bool ok = !text.empty() && text.size() <= 18;
  for (char c : text) {
    if (c < '0' || c > '9') {
      ok = false;
      break;
    }
    v = v * 10 + (c - '0');
  }
  if (!ok || v <= 0 || v > max)
    throw Error(errc::kInvalidParameter,
                what + " must be a positive integer" + (max < INT64_MAX ? " up to " + std::to_string(max) : "") +
                    ", got \"" + text + "\"",
                what);
  return v;
}

std::optional<int> versionParam(const ApiRequest& req) {
  if (!req.hasQueryParam("version")) return std::nullopt;
  return static_cast<int>(positiveInteger(req.queryParam("version"), "version", INT32_MAX));
}

namespace {

constexpr int kDefaultListLimit = 100;
constexpr int kMaxListLimit = 1000;
constexpr size_t kDefaultBatch = 500;
constexpr size_t kMaxBatch = 10000;

bool booleanParam(const ApiRequest& req, const std::string& name) {
  if (!req.hasQueryParam(name)) return false;
  const std::string v = req.queryParam(name);
  if (v == "true" || v == "1" || v.empty()) return true;
  if (v == "false" || v == "0") return false;
  throw Error(errc::kInvalidParameter, name + " must be true or false, got \"" + v + "\"", name);
}

void registerKind(HttpServer& server, Store& store, const std::string& kind) {
  const std::string base = "/" + kind + "s";
  const DocumentLimits limits = documentLimits(server.options().limits);
  const int maxDepth = server.options().limits.maxJsonDepth;
  const RouteOptions write{true, false};

  server.addRoute("POST", base, [&store, kind, limits, base](const ApiRequest& req) {
    const StoredObject created = store.create(prepareDocument(req.body, kind, store, limits, ""));
    refreshPendingDescriptors(store, limits.maxNodes);  // a shape with references is written pending
    ApiResponse out{201, storedObjectJson(created)};
    out.headers.emplace_back("Location", base + "/" + std::to_string(created.id));
    return out;
  }, write);

  server.addRoute("GET", base, [&store, kind](const ApiRequest& req) {
    ListQuery q;
    q.kind = kind;
    if (req.hasQueryParam("name")) q.name = req.queryParam("name");
    if (req.hasQueryParam("version")) {
      if (!q.name) throw Error(errc::kInvalidParameter, "version needs name", "version");
      q.version = static_cast<int>(positiveInteger(req.queryParam("version"), "version", INT32_MAX));
    }
    if (req.hasQueryParam("after")) q.afterId = positiveInteger(req.queryParam("after"), "after");
    q.limit = req.hasQueryParam("limit")
                  ? static_cast<int>(positiveInteger(req.queryParam("limit"), "limit", kMaxListLimit))
                  : kDefaultListLimit;
    const std::vector<StoredObject> found = store.list(q);
    nlohmann::json items = nlohmann::json::array();
    for (const StoredObject& o : found) items.push_back(storedObjectJson(o));
    // Keyset paging: a full page may have more after it.
    nlohmann::json next = nullptr;
    if (static_cast<int>(found.size()) == q.limit && !found.empty()) next = found.back().id;
    return ApiResponse{200, {{"items", items}, {"next_after", next}}};
  });

  server.addRoute("GET", base + "/{id}", [&store, kind](const ApiRequest& req) {
    const int64_t id = positiveInteger(req.pathParams[0], "id");
    return ApiResponse{200, storedObjectJson(store.get(kind, id, versionParam(req)))};
  });

  server.addRoute("PUT", base + "/{id}", [&store, kind, limits](const ApiRequest& req) {
    const int64_t id = positiveInteger(req.pathParams[0], "id");
    nlohmann::json doc = req.body;
    // The name may be left out: a new version keeps the object's name.
    if (doc.is_object() && !doc.contains("name")) doc["name"] = store.get(kind, id).name;
    const StoredObject stored = store.put(id, prepareDocument(doc, kind, store, limits, ""));
    refreshPendingDescriptors(store, limits.maxNodes);  // the objects reaching this one are pending
    return ApiResponse{200, storedObjectJson(stored)};
  }, write);

  server.addRoute("DELETE", base + "/{id}", [&store, kind](const ApiRequest& req) {
    const int64_t id = positiveInteger(req.pathParams[0], "id");
    const std::vector<int64_t> deleted = store.remove(kind, id, booleanParam(req, "cascade"));
    return ApiResponse{200, {{"deleted", deleted}}};
  }, write);

  server.addRoute("POST", base + "/bulk", [&store, kind, limits, maxDepth](const ApiRequest& req) {
    BulkOptions options;
    options.kind = kind;
    options.limits = limits;
    if (req.hasQueryParam("mode")) {
      const std::string mode = req.queryParam("mode");
      if (mode == "create") options.mode = BulkMode::kCreate;
      else if (mode == "upsert") options.mode = BulkMode::kUpsert;
      else throw Error(errc::kInvalidParameter, "mode must be create or upsert, got \"" + mode + "\"", "mode");
    }
    options.batchSize = req.hasQueryParam("batch")
                            ? static_cast<size_t>(positiveInteger(req.queryParam("batch"), "batch", kMaxBatch))
                            : kDefaultBatch;
    const BulkReport report = importDocuments(store, splitBulkBody(req.rawBody(), maxDepth), options);
    return ApiResponse{200, report.toJson()};
  }, RouteOptions{true, true});
}

}  // namespace

void registerObjectRoutes(HttpServer& server, Store& store) {
  registerKind(server, store, "part");
  registerKind(server, store, "shape");
  registerKind(server, store, "curve");
  registerKind(server, store, "surface");
}

}  // namespace fsdb
