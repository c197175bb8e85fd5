// POST /evaluate (inline documents) and the stored-shape forms (docs/api.md §3, §4):
//   POST /shapes/{id}/evaluate        the same answer for a stored shape, cached by content
//   GET  /shapes/{id}/membership      the levels of one point (and /parts/{id}/membership)
//   GET  /shapes/{id}/members         the family's crisp members with their degrees (and /parts/{id}/members)
//   GET  /parts/{id}/params           a part's fourteen fuzzy values, its words resolved
//   GET  /shapes/{id}/mesh            OBJ or binary STL of lower/upper(α), or GLB of both, cached
//   GET  /shapes/{id}/grid.vdb        both grids as a .vdb file, cached
//   POST /mesh                        the same mesh files of an inline document (the studio's
//                                     preview of an edited, unsaved part), single-flighted
// Cache keys hash the shape's document, the documents of everything it references (so any
// change below a shape changes its keys; the store also drops the rows on every write), and
// the request's resolution, alphas and method.
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "db/content_hash.h"
#include "db/store.h"
#include "geometry/core/error.h"
#include "geometry/voxel/envelope_mesh.h"
#include "query/document/part_json.h"
#include "query/json/json_body.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "server/http/response_encoding.h"
#include "server/service/documents.h"
#include "server/service/evaluation.h"
#include "server/service/family_members.h"
#include "server/service/mesh_format.h"
#include "server/service/png_format.h"
#include "server/service/single_flight.h"
#include "server/service/thumbnail.h"

namespace fsdb {

double numberParam(const ApiRequest& req, const std::string& name, std::optional<double> fallback) {
  if (!req.hasQueryParam(name)) {
    if (fallback) return *fallback;
    throw Error(errc::kInvalidParameter, "query parameter " + name + " is required", name);
  }
  const std::string text = req.queryParam(name);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // Every byte must be read: an encoded NUL ("0%00junk") stopped strtod as an end would.
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    throw Error(errc::kInvalidParameter, name + " must be a finite number, got \"" + text + "\"", name);
  return v;
}

namespace {

constexpr int kDefaultExportResolution = 64;

int64_t shapeId(const ApiRequest& req) { return positiveInteger(req.pathParams[0], "id"); }

// Voxels across a thumbnail's shape: enough for 128 pixels once the vertices are on the surface.
constexpr int kThumbnailResolution = 48;

// The stored shape, parsed once (the same parse serves the cache key and, on a miss, the
// evaluation), and a fingerprint of everything it is made of: its document and each referenced
// object's id and document, in the order the parser resolves them.
struct StoredShape {
  StoredObject object;
  ParsedShape parsed;
  std::string fingerprint;
};

// `document` parsed at `path` (its references resolved against the store), and the fingerprint
// of its text `documentText` with every object it references.
ParsedShape parseFingerprinted(const Store& store, const nlohmann::json& document, const std::string& documentText,
                               const std::string& path, size_t maxNodes, std::string* fingerprint) {
  std::string parts = documentText;
  const ReferenceResolver base = storeResolver(store);
  const ReferenceResolver recording = [&](const std::string& kind, const nlohmann::json& key) {
    auto r = base(kind, key);
    if (r) parts += "\n" + kind + ":" + std::to_string(r->id) + ":" + r->document.dump();
    return r;
  };
  ParsedShape parsed = parseShapeField(document, path, maxNodes, recording);
  *fingerprint = contentHash(parts);
  return parsed;
}

StoredShape loadShape(const Store& store, int64_t id, size_t maxNodes, const std::string& kind = "shape") {
  StoredShape s{store.get(kind, id), {}, ""};
  s.parsed = parseFingerprinted(store, nlohmann::json::parse(s.object.documentJson), s.object.documentJson, "",
                                maxNodes, &s.fingerprint);
  return s;
}

std::string cacheKey(const std::string& what, const StoredShape& shape, const std::string& request) {
  return what + ":" + contentHash(shape.fingerprint + "\n" + request);
}

// The resolution of an export: an integer of at least 2 (422), at most --max-resolution (413).
int exportResolution(double r, int maxResolution) {
  if (r != std::floor(r) || r < 2)
    throw Error(errc::kInvalidParameter, "resolution must be an integer of at least 2", "resolution");
  if (r > maxResolution)
    throw Error(errc::kLimitExceeded,
                "resolution " + std::to_string(static_cast<long long>(r)) +
                    " exceeds max_resolution=" + std::to_string(maxResolution),
                "resolution");
  return static_cast<int>(r);
}

// Exports and thumbnails being made, by cache key: a request for one already being made (the
// page and the warm-up asking for the same thumbnail, a double click on an export) waits for it
// instead of extracting the same meshes again; the first request stores it in the cache.
SingleFlight<std::string>& exportFlights() {
  static SingleFlight<std::string> flights;
  return flights;
}

// What a mesh request asks for (GET /{kind}s/{id}/mesh's query, POST /mesh's body), checked.
struct MeshRequest {
  double alpha = 0.5;
  std::string bound = "upper";  // lower | upper; not used by glb (both)
  std::string format = "obj";   // obj | stl | glb
  int resolution = kDefaultExportResolution;

  void check() const {
    if (alpha < 0.0 || alpha > 1.0) throw Error(errc::kInvalidParameter, "alpha lies in [0, 1]", "alpha");
    if (bound != "lower" && bound != "upper")
      throw Error(errc::kInvalidParameter, "bound must be lower or upper, got \"" + bound + "\"", "bound");
    if (format != "obj" && format != "stl" && format != "glb")
      throw Error(errc::kInvalidParameter, "format must be obj, stl or glb, got \"" + format + "\"", "format");
  }
  bool glb() const { return format == "glb"; }  // both bounds in one file: `bound` does not apply
  std::string contentType() const { return glb() ? "model/gltf-binary" : format == "obj" ? "model/obj" : "model/stl"; }
  std::string filename(const std::string& name) const {
    return name + "-" + (glb() ? std::string() : bound + "-") + std::to_string(alpha) + "." + format;
  }
  // The part of a cache key that names the file (with the shape's fingerprint).
  std::string key() const {
    return nlohmann::json{{"alpha", alpha},
                          {"bound", glb() ? "both" : bound},
                          {"format", format},
                          {"resolution", resolution},
                          {"surface", "smooth"}}
        .dump();
  }
};

// The mesh file of a parsed shape: its grid at the request's resolution (a build shared with
// every request for the same fingerprint at that resolution) and the smooth meshes, the grid and
// its meshes together held to --max-eval-ms (the mesh was not: a GLB at 512 took 163 s under a
// 60 s limit). `triangles` receives the count of all meshes in the file.
std::string meshFile(const ParsedShape& shape, const std::string& fingerprint, const MeshRequest& request,
                     const EvaluationLimits& limits, size_t* triangles) {
  const auto started = std::chrono::steady_clock::now();
  const double alpha = request.alpha;
  const Evaluation e =
      evaluateParsedShape({{"resolution", request.resolution}, {"alphas", {alpha}}}, shape, limits, fingerprint);
  *triangles = 0;
  if (request.glb()) {
    std::vector<NamedMesh> both = {{"lower", evaluationMesh(e, alpha, EnvelopeBound::kLower, limits, started)},
                                   {"upper", evaluationMesh(e, alpha, EnvelopeBound::kUpper, limits, started)}};
    for (const NamedMesh& m : both) *triangles += m.second.triangles.size();
    return toGlb(both);
  }
  const TriangleMesh mesh = evaluationMesh(
      e, alpha, request.bound == "lower" ? EnvelopeBound::kLower : EnvelopeBound::kUpper, limits, started);
  *triangles = mesh.triangles.size();
  return request.format == "obj" ? toObj(mesh) : toBinaryStl(mesh);
}

ApiResponse bytesResponse(std::string bytes, const std::string& contentType, const std::string& filename, bool cached,
                          bool inlineView = false) {
  ApiResponse out{200, nullptr, std::move(bytes), contentType};
  // Pictures open in the browser; mesh and grid files download.
  out.headers.emplace_back("Content-Disposition", contentDisposition(inlineView ? "inline" : "attachment", filename));
  out.headers.emplace_back("X-Fsdb-Cache", cached ? "hit" : "miss");
  return out;
}

}  // namespace

void registerEvaluationRoutes(HttpServer& server, Store& store, MemoryBudget* memory) {
  const ServerLimits& serverLimits = server.options().limits;
  const EvaluationLimits limits{serverLimits.maxResolution, serverLimits.maxNodes, serverLimits.maxGridMb,
                                serverLimits.maxEvalMs, serverLimits.maxMemoryMb > 0 ? memory : nullptr};
  const int maxDepth = server.options().limits.maxJsonDepth;

  // Grid builds and meshes are heavy (RouteOptions::heavy): at most half the workers serve them.
  const RouteOptions heavy{false, false, true};
  server.addRoute(
      "POST", "/evaluate",
      [limits, &store](const ApiRequest& req) {
        return ApiResponse{200, evaluateRequest(req.body, limits, storeResolver(store))};
      },
      heavy);

  // The body ({"resolution","alphas","method"}) may be empty: the defaults of POST /evaluate.
  server.addRoute(
      "POST", "/shapes/{id}/evaluate",
      [limits, maxDepth, &store](const ApiRequest& req) {
        nlohmann::json request = nlohmann::json::object();
        if (req.rawBody().find_first_not_of(" \t\r\n") != std::string::npos)
          request = parseJsonBody(req.rawBody(), maxDepth);
        requireObject(request, "");
        const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes);
        const std::string key = cacheKey("evaluate", shape, request.dump());
        if (auto hit = store.cachedEvaluation(key)) {
          nlohmann::json result = nlohmann::json::parse(hit->resultJson);
          result["cached"] = true;
          return ApiResponse{200, result};
        }
        nlohmann::json result = evaluateParsedShape(request, shape.parsed, limits, shape.fingerprint).result;
        result["shape_id"] = shape.object.id;
        result["shape_version"] = shape.object.version;
        store.storeEvaluation(shape.object.id, key, {result.dump(), ""});
        result["cached"] = false;
        return ApiResponse{200, result};
      },
      RouteOptions{false, true, true});

  // docs/api.md §4: "upper" is the highest α with the point in upper(α). "lower" as docs/api.md
  // words it (the highest α with the point in lower(α)) is 1 or 0, because lower(α) grows with α;
  // the informative number is "lower_from", the lowest α from which the point is necessarily
  // inside (null when never), and "necessity" = 1 − lower_from (Zhang, Pham & Chen, §3.2;
  // alpha_field.h).
  for (const std::string kind : {"shape", "part"}) {
    server.addRoute("GET", "/" + kind + "s/{id}/membership", [limits, &store, kind](const ApiRequest& req) {
      const Vec3 p{numberParam(req, "x", std::nullopt), numberParam(req, "y", std::nullopt),
                   numberParam(req, "z", std::nullopt)};
      const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes, kind);
      const AlphaLevels levels = shape.parsed.field->levelsAt(p);
      // The field is fresh per request, so its count is this point's searches alone.
      const std::uint64_t exhausted = shape.parsed.field->budgetExhaustions();
      const bool everInLower = levels.lower <= 1.0f;
      return ApiResponse{200,
                         {{"point", {p.x, p.y, p.z}},
                          {"upper", levels.upper},
                          {"lower", everInLower ? 1.0 : 0.0},
                          {"lower_from", everInLower ? nlohmann::json(levels.lower) : nlohmann::json(nullptr)},
                          {"necessity", everInLower ? 1.0 - levels.lower : 0.0},
                          {"exhausted_searches", exhausted},
                          {"exact", exhausted == 0}}};
    });
  }

  // The family's members (server/service/family_members.h; Zhang, Pham & Chen, Figure 1): crisp
  // documents drawn from the fuzzy values, with their membership degrees, from the core outward.
  for (const std::string kind : {"shape", "part"}) {
    server.addRoute("GET", "/" + kind + "s/{id}/members", [limits, &store, kind](const ApiRequest& req) {
      const double count = numberParam(req, "count", 9);
      if (count != std::floor(count)) throw Error(errc::kInvalidParameter, "count is a whole number", "count");
      const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes, kind);
      nlohmann::json answer = familyMembers(shape.parsed, kind == "part", static_cast<int>(std::max(-1.0, std::min(count, 1e6))),
                                            limits.maxNodes);
      answer["id"] = shape.object.id;
      answer["kind"] = kind;
      answer["version"] = shape.object.version;
      return ApiResponse{200, std::move(answer)};
    });
  }

  // A part's fourteen fuzzy values as the server reads them: its words resolved, the defaults
  // filled in, every value in its normal form (a number, tri, trap or points). A part made from
  // words stores only its text, so this is what an editor of its values starts from.
  server.addRoute("GET", "/parts/{id}/params", [&store](const ApiRequest& req) {
    const StoredObject object = store.get("part", shapeId(req), versionParam(req));
    nlohmann::json answer = partToJson(parsePart(nlohmann::json::parse(object.documentJson), ""));
    answer["id"] = object.id;
    answer["version"] = object.version;
    return ApiResponse{200, std::move(answer)};
  });

  for (const std::string kind : {"shape", "part"}) {
    server.addRoute("GET", "/" + kind + "s/{id}/mesh", [limits, &store, kind](const ApiRequest& req) {
      MeshRequest request;
      request.alpha = numberParam(req, "alpha", 0.5);
      if (req.hasQueryParam("bound")) request.bound = req.queryParam("bound");
      if (req.hasQueryParam("format")) request.format = req.queryParam("format");
      request.check();
      request.resolution =
          exportResolution(numberParam(req, "resolution", kDefaultExportResolution), limits.maxResolution);
      const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes, kind);
      const std::string filename = request.filename(shape.object.name);
      const std::string key = cacheKey("mesh", shape, request.key());
      if (auto hit = store.cachedEvaluation(key)) return bytesResponse(hit->vdb, request.contentType(), filename, true);
      std::string bytes = exportFlights().run(key, [&] {
        size_t triangles = 0;
        std::string made = meshFile(shape.parsed, shape.fingerprint, request, limits, &triangles);
        store.storeEvaluation(shape.object.id, key, {nlohmann::json{{"triangles", triangles}}.dump(), made});
        return made;
      });
      return bytesResponse(std::move(bytes), request.contentType(), filename, false);
    }, heavy);
  }

  // The mesh of an inline document (the studio's live preview of an edited part, and meshes of
  // older versions and of family members): the same files and limits as the stored form. It is
  // not kept in the evaluation cache, whose rows belong to a stored object and go with its
  // writes; an inline document has no such owner. Requests for the same content at the same
  // moment still make it once (the export flights, keyed by the document and what it
  // references, and the grid build shared with a stored object of the same fingerprint).
  server.addRoute("POST", "/mesh", [limits, &store](const ApiRequest& req) {
    const nlohmann::json& body = req.body;
    requireObject(body, "");
    rejectUnknownKeys(body, "", {"shape", "alpha", "bound", "format", "resolution"});
    MeshRequest request;
    request.alpha = optionalNumberIn(body, "", "alpha", 0.5, 0.0, 1.0);
    if (body.contains("bound")) request.bound = requireString(body["bound"], "bound");
    if (body.contains("format")) request.format = requireString(body["format"], "format");
    request.check();
    if (body.contains("resolution"))
      request.resolution = exportResolution(requireNumber(body["resolution"], "resolution"), limits.maxResolution);
    const nlohmann::json& document = requireField(body, "shape", "");
    std::string fingerprint;
    const ParsedShape parsed =
        parseFingerprinted(store, document, document.dump(), "shape", limits.maxNodes, &fingerprint);
    const std::string name = document.is_object() && document.contains("name") && document["name"].is_string()
                                 ? document["name"].get<std::string>()
                                 : std::string("mesh");
    const std::string key = "inline-mesh:" + contentHash(fingerprint + "\n" + request.key());
    std::string bytes = exportFlights().run(key, [&] {
      size_t triangles = 0;
      return meshFile(parsed, fingerprint, request, limits, &triangles);
    });
    return bytesResponse(std::move(bytes), request.contentType(), request.filename(name), false);
  }, heavy);

  // Thumbnails of stored shapes and parts: lower(α) solid and upper(α) translucent
  // (server/service/thumbnail.h), from smooth meshes at 48 voxels across, cached by content.
  for (const std::string kind : {"shape", "part"}) {
    server.addRoute("GET", "/" + kind + "s/{id}/thumbnail.png", [limits, &store, kind](const ApiRequest& req) {
      const double alpha = numberParam(req, "alpha", 0.5);
      if (alpha < 0.0 || alpha > 1.0) throw Error(errc::kInvalidParameter, "alpha lies in [0, 1]", "alpha");
      const double size = numberParam(req, "size", 128);
      if (size != std::floor(size) || size < 16 || size > 512)
        throw Error(errc::kInvalidParameter, "size is an integer in [16, 512]", "size");
      const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes, kind);
      const std::string filename = shape.object.name + ".png";
      const std::string key = cacheKey("thumbnail", shape, nlohmann::json{{"alpha", alpha}, {"size", size}}.dump());
      if (auto hit = store.cachedEvaluation(key)) return bytesResponse(hit->vdb, "image/png", filename, true, true);
      std::string bytes = exportFlights().run(key, [&] {
        const auto started = std::chrono::steady_clock::now();
        const Evaluation e = evaluateParsedShape({{"resolution", kThumbnailResolution}, {"alphas", {alpha}}},
                                                 shape.parsed, limits, shape.fingerprint);
        std::string made = toPng(renderThumbnail(evaluationMesh(e, alpha, EnvelopeBound::kLower, limits, started),
                                                 evaluationMesh(e, alpha, EnvelopeBound::kUpper, limits, started),
                                                 static_cast<int>(size)));
        store.storeEvaluation(shape.object.id, key, {"{}", made});
        return made;
      });
      return bytesResponse(std::move(bytes), "image/png", filename, false, true);
    }, heavy);
  }

  server.addRoute("GET", "/shapes/{id}/grid.vdb", [limits, &store](const ApiRequest& req) {
    const int resolution =
        exportResolution(numberParam(req, "resolution", kDefaultExportResolution), limits.maxResolution);
    const StoredShape shape = loadShape(store, shapeId(req), limits.maxNodes);
    const std::string filename = shape.object.name + ".vdb";
    const std::string key = cacheKey("vdb", shape, std::to_string(resolution));
    if (auto hit = store.cachedEvaluation(key))
      return bytesResponse(hit->vdb, "application/octet-stream", filename, true);
    std::string bytes = exportFlights().run(key, [&] {
      const Evaluation e =
          evaluateParsedShape({{"resolution", resolution}, {"alphas", {1.0}}}, shape.parsed, limits, shape.fingerprint);
      std::string made = vdbBytes(*e.grid);
      store.storeEvaluation(shape.object.id, key, {"{}", made});
      return made;
    });
    return bytesResponse(std::move(bytes), "application/octet-stream", filename, false);
  }, heavy);
}

}  // namespace fsdb
