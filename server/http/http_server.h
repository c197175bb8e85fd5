#pragma once
// fsdb's HTTP server: cpp-httplib underneath, JSON in and out, one error format.
//
// Contract:
// - Every response body is JSON (except exports that name another media type). Every failure is
//   {"error":{"code","message","path"}} with the status of server/service/error_json.h, including
//   unknown routes (404), wrong methods (405), oversized bodies (413) and handler exceptions
//   (500). A bad request never stops the server.
// - Routes are registered through addRoute(), which records them; routes() is what
//   GET /openapi.json must describe (a test holds the two equal).
// - start() binds before it returns, so the caller can print the real port (`--port 0`).
// - A GET answered 200 carries a weak ETag of its body, unless its handler set one (a stored
//   object: its version, strong, for If-Match), and is 304 without a body when If-None-Match names it
//   (server/http/response_encoding.h); binary exports (meshes, grids) are gzipped when the client accepts it (JSON and
//   SVG by cpp-httplib itself).
// - CORS is off unless ServerOptions::corsOrigin is set.
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "server/http/metrics.h"
#include "server/service/limits.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace fsdb {

class ConnectionFront;

struct ServerOptions {
  std::string host = "127.0.0.1";
  // --token / FSDB_TOKEN: when set, write routes need "Authorization: Bearer <token>" (401
  // unauthorized otherwise). Reads never need it.
  std::string token;
  int port = 8080;  // 0: pick a free port
  int threads = 0;  // 0: hardware concurrency, at least 16 (workers take whole requests from the front)
  // Build the stored shapes' graphs of structural search in the background at start
  // (server/service/graph_warmup.h); --no-warm-graphs turns it off.
  bool warmGraphs = true;
  // --cors ORIGIN: answers carry Access-Control-Allow-Origin: ORIGIN and OPTIONS preflights are
  // answered, so a page served from ORIGIN may call the API; empty (the default): no CORS.
  std::string corsOrigin;
  // --web DIR: the studio page's folder, served at / (files only: a path no file has goes on to
  // the API routes); empty: no page.
  std::string webRoot;
  // --warm-thumbnails: after the start, draw the thumbnail (α 0.5, 128 pixels) of every stored
  // shape and part that has none cached, in the background, as a browser would ask for them, so
  // the studio page's first view finds them ready (`make serve` turns it on).
  bool warmThumbnails = false;
  // --max-cache-mb: the bound of the store's evaluation cache (db/store.h StoreOptions::
  // maxCacheBytes), least recently used out first; 0: none.
  std::uint64_t maxCacheMb = 1024;
  // --read-timeout-ms: from its first byte, a request's head and its body up to 1 MiB must arrive
  // within this (plus the body at 64 KiB/s), else 408 and the connection closes
  // (server/http/connection_front.h). Slow connections wait there, never on a worker.
  int readTimeoutMs = 10000;
  ServerLimits limits;
};

// Whether `origin` may follow --cors: "*" or scheme://host[:port] (http or https, no path).
bool validCorsOrigin(const std::string& origin);

// What a handler gets: the parsed JSON body (null for GET and raw-body routes), the raw request
// for query strings, and the body bytes as received.
struct ApiRequest {
  const httplib::Request& raw;
  nlohmann::json body;
  std::vector<std::string> pathParams;  // values of the route's {name} segments, in order
  std::string bodyBytes;                // POST and PUT: the body (read by the server, never by httplib: see addRoute)
  std::string queryParam(const std::string& name) const;  // "" when absent
  bool hasQueryParam(const std::string& name) const;
  std::optional<std::string> header(const std::string& name) const;  // nullopt when absent
  const std::string& rawBody() const { return bodyBytes; }           // raw-body routes read it
};

// What a handler returns: status + JSON, or (for exports) a body with its own media type.
struct ApiResponse {
  ApiResponse() = default;
  ApiResponse(int s, nlohmann::json j, std::string raw = {}, std::string type = {})
      : status(s), json(std::move(j)), rawBody(std::move(raw)), contentType(std::move(type)) {}
  int status = 200;
  nlohmann::json json;
  std::string rawBody;                                       // used when contentType is not JSON
  std::string contentType;                                   // "" = application/json
  std::vector<std::pair<std::string, std::string>> headers;  // extra headers (Location, ...)
};

struct RouteOptions {
  bool write = false;    // changes the database: needs the bearer token when one is set
  bool rawBody = false;  // the handler reads raw.body itself (JSON Lines); body stays null
  // Builds a grid or a mesh (seconds, and a worker all the while): at most half the workers
  // serve such requests at once, the next is 503 overloaded with Retry-After, so that cheap
  // requests (/health, reads, searches) always find a worker. 16 evaluations at once held all
  // 16 workers and /health waited 10 s.
  bool heavy = false;
};

using ApiHandler = std::function<ApiResponse(const ApiRequest&)>;

struct Route {
  std::string method;       // "GET", "POST", ...
  std::string openapiPath;  // "/operators/evaluate", "/parts/{id}"
};

class HttpServer {
 public:
  explicit HttpServer(ServerOptions options);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Registers a handler. `openapiPath` uses OpenAPI templating ("/parts/{id}"); each {name}
  // matches one path segment. Handlers throw fsdb::Error for client errors.
  void addRoute(const std::string& method, const std::string& openapiPath, ApiHandler handler,
                RouteOptions routeOptions = {});
  const std::vector<Route>& routes() const { return routes_; }
  const ServerOptions& options() const { return options_; }

  // Binds host:port (port 0 picks one) and returns the bound port, listening with the kernel's
  // largest backlog (SOMAXCONN); throws std::runtime_error when the address cannot be bound.
  int bind();
  // Serves until stop(); returns after in-flight requests are answered, at once when stop() came
  // first.
  void listen();
  // Thread-safe; stops accepting and makes listen() return. Called before listen(), it waits for
  // listen() to be called (which then returns at once), so a stop is never lost.
  void stop();

  // What GET /metrics counts (server/http/metrics.h); requests are queued while they wait for a
  // worker (whole, from the front), and in flight from their request line to their answer.
  Metrics& metrics() { return metrics_; }
  int connectionsQueued() const { return queued_.load(); }
  int connectionsOpen() const;  // in the front (idle, or a request arriving) and with workers
  int requestsInFlight() const { return inFlight_.load(); }
  int workerThreads() const { return workerThreads_; }

 private:
  void installHandlers();
  // The methods of the routes whose pattern matches `path` ("GET, PUT"), the studio page's GET
  // included; "" when none does.
  std::string allowedMethods(const std::string& path) const;
  // Answers 405 method_not_allowed with Allow when `path` has routes but none for `method`;
  // false (nothing written) otherwise.
  bool refuseMethod(const std::string& method, const std::string& path, httplib::Response& res) const;
  // Whether a request may send its body: not a write route without the bearer token (when one is set).
  bool mayContinue(const std::string& method, const std::string& path, const std::string& authorization) const;

  ServerOptions options_;
  std::unique_ptr<httplib::Server> server_;
  std::vector<Route> routes_;
  std::vector<std::regex> routePatterns_;  // routes_[i]'s path pattern, compiled once (405 lookup)
  std::vector<bool> routeWrites_;          // routes_[i] needs the token (RouteOptions::write)
  std::atomic<bool> stopRequested_{false};
  std::atomic<bool> listenReturned_{false};
  int listenSocket_ = -1;  // set by httplib's socket callback when it binds
  std::atomic<ConnectionFront*> front_{nullptr};  // while listen() serves
  std::mutex frontMutex_;                         // stop() against the front's end
  Metrics metrics_;
  std::atomic<int> queued_{0}, inFlight_{0};
  std::atomic<int> heavy_{0};  // requests of heavy routes being served
  int workerThreads_ = 0;
};

}  // namespace fsdb
