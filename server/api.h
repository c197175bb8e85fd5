#pragma once
// Registration of fsdb's endpoints on an HttpServer, one function per resource family.
// Each endpoint registered here must appear in schema/openapi.json (tests/server/openapi_test).
namespace fsdb {
class HttpServer;
class Store;

// GET /health (with the store's counts), GET /openapi.json
void registerServiceRoutes(HttpServer& server, const Store& store);
// GET /operators, POST /operators/evaluate
void registerOperatorRoutes(HttpServer& server);

// POST /evaluate (references in inline documents resolve against the store), and the stored-shape
// forms: POST /shapes/{id}/evaluate (cached), GET /shapes/{id}/membership, /mesh, /grid.vdb
void registerEvaluationRoutes(HttpServer& server, Store& store);

// POST/GET /parts, GET/PUT/DELETE /parts/{id}, POST /parts/bulk, and the same for /shapes
void registerObjectRoutes(HttpServer& server, Store& store);

// Every route family above, in order.
void registerAllRoutes(HttpServer& server, Store& store);
}  // namespace fsdb
