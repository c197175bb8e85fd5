#pragma once
// Registration of fsdb's endpoints on an HttpServer, one function per resource family.
// Each endpoint registered here must appear in schema/openapi.json (tests/server/http/openapi_routes_test).
#include <cstdint>
#include <optional>
#include <string>

namespace fsdb {
class HttpServer;
class Store;
class MemoryBudget;
struct ApiRequest;
struct BezierJsonLimits;
struct ServerLimits;

// GET /health (with the store's counts), GET /openapi.json, GET /metrics (server/http/metrics.h,
// with the gauges of the server, the store and `memory`)
void registerServiceRoutes(HttpServer& server, const Store& store, const MemoryBudget& memory);
// GET /operators, POST /operators/evaluate
void registerOperatorRoutes(HttpServer& server);
// GET /vocabulary (query/linguistic/vocabulary.h: activeVocabulary())
void registerVocabularyRoutes(HttpServer& server);

// POST /evaluate (references in inline documents resolve against the store), and the stored-shape
// forms: POST /shapes/{id}/evaluate (cached), GET /shapes/{id}/membership, /mesh, /grid.vdb, and
// POST /mesh (the mesh of an inline document)
// Grids and meshes reserve their memory from `memory` (when --max-memory-mb is not 0).
void registerEvaluationRoutes(HttpServer& server, Store& store, MemoryBudget* memory);

// POST/GET /parts, GET/PUT/DELETE /parts/{id}, POST /parts/bulk, and the same for /shapes,
// /curves and /surfaces
void registerObjectRoutes(HttpServer& server, Store& store);

// POST /curves/bezier/evaluate, /elevate, /defuzzify, POST /surfaces/bezier/evaluate, /elevate,
// /iso, and the exports of stored curves and surfaces: GET /curves/{id}/svg, /surfaces/{id}/mesh
void registerBezierRoutes(HttpServer& server, const Store& store);
// The Bézier limits of `fsdb serve` (--max-control-points, --max-curve-points) for
// query/document/bezier_json.h; every curve and surface route reads documents through them.
BezierJsonLimits bezierLimits(const ServerLimits& limits);

// POST /query/linguistic (server/service/linguistic_search.h), POST /query/csg (server/service/csg_search.h)
void registerQueryRoutes(HttpServer& server, const Store& store);

// POST /curves/fair, GET /curves/{id}/candidates (the fair curves of Bernardes, Wu & D'Ottaviano;
// server/http/fair_curve_api.cpp)
void registerFairCurveRoutes(HttpServer& server, const Store& store);

// A positive integer from a path segment or query parameter (digits only, at most `max`);
// 422 invalid_parameter naming `what` otherwise. Every {id} of every route goes through it.
int64_t positiveInteger(const std::string& text, const std::string& what, int64_t max = INT64_MAX);
// A finite number from query parameter `name`, `fallback` when absent (required when none);
// 422 invalid_parameter naming it otherwise.
double numberParam(const ApiRequest& req, const std::string& name, std::optional<double> fallback);
// The ?version= of a stored-object route (a positive integer), nullopt when absent (the latest).
std::optional<int> versionParam(const ApiRequest& req);

// Every route family above, in order.
void registerAllRoutes(HttpServer& server, Store& store);
}  // namespace fsdb
