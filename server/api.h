#pragma once
// Registration of fsdb's endpoints on an HttpServer, one function per resource family.
// Each endpoint registered here must appear in schema/openapi.json (tests/server/openapi_test).
namespace fsdb {
class HttpServer;

// GET /health, GET /openapi.json
void registerServiceRoutes(HttpServer& server);
// GET /operators, POST /operators/evaluate
void registerOperatorRoutes(HttpServer& server);

// POST /evaluate
void registerEvaluationRoutes(HttpServer& server);

// Every route family above, in order.
void registerAllRoutes(HttpServer& server);
}  // namespace fsdb
