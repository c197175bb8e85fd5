// Parts, shapes, curves and surfaces (docs/api.md §4, §6): create, read (any version), list, new
// versions, delete, bulk. One set of handlers serves every kind; the route's kind is checked against the document's.
#include <algorithm>

#include "geometry/core/error.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/service/bulk_import.h"
#include "server/service/descriptor_rows.h"
#include "server/service/documents.h"

namespace fsdb {

int64_t positiveInteger(const std::string& text, const std::string& what, int64_t max) {
  int64_t v = 0;
  // At most 18 digits, which int64_t holds; a longer text is refused before any digit is taken
  // (it was read on, and 19 nines overflowed: undefined behaviour UBSan found).
  bool ok = !text.empty() && text.size() <= 18;
  for (size_t i = 0; ok && i < text.size(); ++i) {
    ok = text[i] >= '0' && text[i] <= '9';
    if (ok) v = v * 10 + (text[i] - '0');
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

// The strong entity tag of a stored object's version (RFC 9110 §8.8.3): "3" for version 3.
std::string versionTag(int version) { return "\"" + std::to_string(version) + "\""; }

// The version a PUT or DELETE requires by If-Match (RFC 9110 §13.1.1), or nullopt without one (or
// with "*": any current version). Strong comparison: a weak tag (W/"3") or a tag that is no
// version of this object never matches, so the write is 412. With several tags, the one equal to
// the latest version now is passed on; the store checks it again under its write lock.
std::optional<int> ifMatchVersion(const ApiRequest& req, const Store& store, const std::string& kind, int64_t id) {
  const std::optional<std::string> given = req.header("If-Match");
  if (!given) return std::nullopt;
  const std::string& header = *given;
  std::vector<int> versions;
  size_t start = 0;
  while (start < header.size()) {
    size_t end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    std::string tag = header.substr(start, end - start);
    tag.erase(0, tag.find_first_not_of(" \t"));
    tag.erase(tag.find_last_not_of(" \t") + 1);
    if (tag == "*") return std::nullopt;
    if (tag.size() > 2 && tag.size() < 12 && tag.front() == '"' && tag.back() == '"' &&
        tag.find_first_not_of("0123456789", 1) == tag.size() - 1)
      versions.push_back(std::stoi(tag.substr(1, tag.size() - 2)));
    start = end + 1;
  }
  const auto refuse = [&](int latest) {
    return Error(errc::kPreconditionFailed,
                 "If-Match " + header + " names no current version of " + kind + " " + std::to_string(id) +
                     (latest > 0 ? "; its ETag is now " + versionTag(latest) : ""),
                 "If-Match");
  };
  if (versions.empty()) throw refuse(0);
  if (versions.size() == 1) return versions[0];
  const int latest = store.get(kind, id).version;
  if (std::find(versions.begin(), versions.end(), latest) == versions.end()) throw refuse(latest);
  return latest;
}

// The store's precondition_failed, at the header that caused it and naming the tag to read again.
template <class Write>
auto conditional(const Store& store, const std::string& kind, int64_t id, Write write) {
  try {
    return write();
  } catch (const Error& e) {
    if (e.code() != std::string(errc::kPreconditionFailed)) throw;
    std::string message = e.what();
    if (std::optional<StoredObject> now = store.find(ObjectReference{kind, id, "", ""}))
      message += "; its ETag is now " + versionTag(now->version);
    throw Error(e.code(), message, "If-Match");
  }
}

// A stored object's answer with its version's tag.
ApiResponse taggedObject(int status, const StoredObject& object) {
  ApiResponse out{status, nullptr, storedObjectText(object), "application/json"};
  out.headers.emplace_back("ETag", versionTag(object.version));
  return out;
}

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
  const size_t maxBulkErrors = server.options().limits.maxBulkErrors;
  const RouteOptions write{true, false};

  server.addRoute(
      "POST", base,
      [&store, kind, limits, base](const ApiRequest& req) {
        const StoredObject created = store.create(prepareDocument(req.body, kind, store, limits, ""));
        refreshPendingDescriptors(store, limits.maxNodes);  // a shape with references is written pending
        ApiResponse out = taggedObject(201, created);
        out.headers.emplace_back("Location", base + "/" + std::to_string(created.id));
        return out;
      },
      write);

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
    // {"items":[...],"next_after":...} with each item spliced as text (storedObjectText).
    std::string body = "{\"items\":[";
    for (size_t i = 0; i < found.size(); ++i) body += (i ? "," : "") + storedObjectText(found[i]);
    // Keyset paging: a full page may have more after it.
    const bool more = static_cast<int>(found.size()) == q.limit && !found.empty();
    body += "],\"next_after\":" + (more ? std::to_string(found.back().id) : std::string("null")) + "}";
    return ApiResponse{200, nullptr, std::move(body), "application/json"};
  });

  server.addRoute("GET", base + "/{id}", [&store, kind](const ApiRequest& req) {
    const int64_t id = positiveInteger(req.pathParams[0], "id");
    return taggedObject(200, store.get(kind, id, versionParam(req)));
  });

  server.addRoute(
      "PUT", base + "/{id}",
      [&store, kind, limits](const ApiRequest& req) {
        const int64_t id = positiveInteger(req.pathParams[0], "id");
        const std::optional<int> ifVersion = ifMatchVersion(req, store, kind, id);
        nlohmann::json doc = req.body;
        // The name may be left out: a new version keeps the object's name.
        if (doc.is_object() && !doc.contains("name")) doc["name"] = store.get(kind, id).name;
        const NewObject object = prepareDocument(doc, kind, store, limits, "");
        const StoredObject stored = conditional(store, kind, id, [&] { return store.put(id, object, ifVersion); });
        refreshPendingDescriptors(store, limits.maxNodes);  // the objects reaching this one are pending
        return taggedObject(200, stored);
      },
      write);

  server.addRoute(
      "DELETE", base + "/{id}",
      [&store, kind](const ApiRequest& req) {
        const int64_t id = positiveInteger(req.pathParams[0], "id");
        const std::optional<int> ifVersion = ifMatchVersion(req, store, kind, id);
        const bool cascade = booleanParam(req, "cascade");
        const std::vector<int64_t> deleted =
            conditional(store, kind, id, [&] { return store.remove(kind, id, cascade, ifVersion); });
        return ApiResponse{200, {{"deleted", deleted}}};
      },
      write);

  server.addRoute(
      "POST", base + "/bulk",
      [&store, kind, limits, maxDepth, maxBulkErrors](const ApiRequest& req) {
        BulkOptions options;
        options.kind = kind;
        options.limits = limits;
        options.maxErrors = maxBulkErrors;
        if (req.hasQueryParam("mode")) {
          const std::string mode = req.queryParam("mode");
          if (mode == "create") options.mode = BulkMode::kCreate;
          else if (mode == "upsert") options.mode = BulkMode::kUpsert;
          else throw Error(errc::kInvalidParameter, "mode must be create or upsert, got \"" + mode + "\"", "mode");
        }
        options.batchSize = req.hasQueryParam("batch")
                                ? static_cast<size_t>(positiveInteger(req.queryParam("batch"), "batch", kMaxBatch))
                                : kDefaultBatch;
        const BulkReport report = importBody(store, req.rawBody(), maxDepth, options);
        return ApiResponse{200, report.toJson()};
      },
      RouteOptions{true, true});
}

}  // namespace

void registerObjectRoutes(HttpServer& server, Store& store) {
  registerKind(server, store, "part");
  registerKind(server, store, "shape");
  registerKind(server, store, "curve");
  registerKind(server, store, "surface");
}

}  // namespace fsdb
