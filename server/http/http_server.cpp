#include "server/http/http_server.h"

#include <httplib.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <regex>
#include <thread>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "server/http/connection_front.h"
#include "server/http/response_encoding.h"
#include "server/service/error_json.h"
#include "server/service/memory_budget.h"

namespace fsdb {
namespace {

// The studio page's paths (served by GET when --web names a folder).
// The page's own modules are /modules/NAME.js (web/modules), so a new one needs no change here.
const char* const kStudioPaths =
    R"(/|/index\.html|/studio\.(js|css)|/modules/[A-Za-z0-9_-]+\.js|/vendor/[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)*)";

// kStudioPaths compiled once, for the 405 lookup and the metrics' "page" series.
bool isStudioPath(const std::string& path) {
  static const std::regex studio(kStudioPaths);
  return std::regex_match(path, studio);
}

// Start time of the request a worker thread is serving; set by the pre-routing handler and
// read by the logger, both of which run on the thread that serves the request.
thread_local std::chrono::steady_clock::time_point tRequestStart;
// The route template that answered (set by addRoute's wrapper), and the error code of an error
// answer (set by sendError), read by the logger for the metrics; reset per request.
thread_local const std::string* tRoute = nullptr;
thread_local std::string tErrorCode;

// "/parts/{id}/mesh" -> "^/parts/([^/]+)/mesh$"
std::string routeRegex(const std::string& openapiPath) {
  static const std::regex param("\\{[^}/]+\\}");
  return std::regex_replace(openapiPath, param, "([^/]+)");
}

void sendJson(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  // error_handler_t::replace: a stray invalid UTF-8 byte in an echoed string must not turn a
  // client error into a server exception.
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

// Compares in time that depends on the token's length only, never on where or whether the
// header differs (its length included), so the token cannot be found byte by byte, nor its
// length, from response times.
bool bearerMatches(const std::string& header, const std::string& token) {
  const std::string expected = "Bearer " + token;
  size_t diff = header.size() ^ expected.size();
  for (size_t i = 0; i < expected.size(); ++i) {
    const unsigned char got = i < header.size() ? static_cast<unsigned char>(header[i]) : 0;
    diff |= static_cast<unsigned char>(got ^ static_cast<unsigned char>(expected[i]));
  }
  return diff == 0;
}

// An unauthenticated write's body (or any refused before it is read) is not wanted: it is read
// and dropped, never kept or parsed.
// It is still read to its end, because httplib keeps the connection open after any answer and
// would read what is left of the body as the next requests. A client that asks first
// (Expect: 100-continue; curl does for bodies over 1 MiB) is answered 401 before it sends one.
void drainUnauthorizedBody(const httplib::ContentReader& content) {
  content([](const char*, size_t) { return true; });
}

Error unauthorizedError() {
  return Error(errc::kUnauthorized,
               "this server requires \"Authorization: Bearer <token>\" for writes (fsdb serve --token)", "");
}

// The store failed (storage_error, 503): an operator must see why in the log, not only the
// client. During an outage every request fails the same way, so one line a second at most,
// with the count of those not written.
void warnStorageFailure(const httplib::Request& req, const Error& e) {
  static std::mutex mutex;
  static std::chrono::steady_clock::time_point last{};
  static size_t unwritten = 0;
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mutex);
  if (last != std::chrono::steady_clock::time_point{} && now - last < std::chrono::seconds(1)) {
    ++unwritten;
    return;
  }
  last = now;
  const size_t before = unwritten;
  unwritten = 0;
  if (before == 0) spdlog::warn("{} {}: database failure (503): {}", req.method, req.path, e.what());
  else
    spdlog::warn("{} {}: database failure (503): {} ({} more failures in the last second)", req.method, req.path,
                 e.what(), before);
}

// Reads a POST or PUT body through httplib's ContentReader into *body (see addRoute for why).
// Multipart bodies are drained and refused (415); a body over maxBody, which httplib checks only
// against Content-Length and not for chunked transfers, is 413 and closes the connection.
void readBody(const httplib::Request& req, const httplib::ContentReader& content, size_t maxBody, std::string* body,
              httplib::Response& res) {
  if (req.is_multipart_form_data()) {
    content([](const httplib::MultipartFormData&) { return true; }, [](const char*, size_t) { return true; });
    throw Error(errc::kUnsupportedMediaType,
                "multipart/form-data bodies are not accepted; send the document itself "
                "(Content-Type: application/json, or JSON Lines for bulk imports)",
                "body");
  }
  bool tooLarge = false;
  size_t discarded = 0;
  const bool read = content([&](const char* data, size_t n) {
    if (!tooLarge && body->size() + n <= maxBody) {
      body->append(data, n);
      return true;
    }
    // Over the limit: drop what was kept and read on without keeping, so that a client still
    // sending sees the 413 instead of a reset connection; up to 4 × max_body_bytes, then stop
    // reading (the connection closes).
    tooLarge = true;
    std::string().swap(*body);
    discarded += n;
    return discarded <= 4 * maxBody;
  });
  // httplib sets 413 when the Content-Length is over its payload limit (max_body_bytes too).
  if (tooLarge || (!read && res.status == 413)) {
    res.set_header("Connection", "close");
    throw Error(errc::kLimitExceeded, "request body larger than max_body_bytes=" + std::to_string(maxBody), "body");
  }
  if (!read) {
    res.set_header("Connection", "close");
    throw Error(errc::kMalformedJson,
                "the request body ended before its announced length (or its chunks were malformed)", "body");
  }
}

// A GET's 200: its ETag, 304 when the client has it, gzip for binary exports the client accepts.
void conditionalAndEncoded(const httplib::Request& req, httplib::Response& res) {
  // A handler may tag the answer itself (a stored object: its version, for If-Match).
  std::string tag = res.get_header_value("ETag");
  if (tag.empty()) {
    tag = entityTag(res.body);
    res.set_header("ETag", tag);
  }
  if (req.has_header("If-None-Match") && ifNoneMatchHits(req.get_header_value("If-None-Match"), tag)) {
    res.status = 304;
    res.body.clear();
    return;
  }
  const std::string type = res.get_header_value("Content-Type");
  if (compressedHere(type)) {
    res.set_header("Vary", "Accept-Encoding");
    if (acceptsGzip(req.get_header_value("Accept-Encoding"))) {
      res.body = gzipBody(res.body);
      res.set_header("Content-Encoding", "gzip");
    }
  }
}

// A file of the studio page (the route's pattern admits no "..": segments are names).
void serveStatic(const std::string& root, const httplib::Request& req, httplib::Response& res) {
  const std::string relative = req.path == "/" ? "index.html" : req.path.substr(1);
  if (relative.find("..") != std::string::npos) {
    sendJson(res, 404, errorBody(errc::kNotFound, "no file " + req.path, ""));
    return;
  }
  // A folder (/vendor/addons) opens as a stream too, and its first read throws: only plain files.
  const std::filesystem::path file = std::filesystem::path(root) / relative;
  std::error_code notAFile;
  std::ifstream in;
  if (std::filesystem::is_regular_file(file, notAFile)) in.open(file, std::ios::binary);
  if (!in.is_open()) {
    sendJson(res, 404, errorBody(errc::kNotFound, "no file " + req.path + " in the studio page", ""));
    return;
  }
  std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The tag of the file itself, checked before anything is compressed: a revalidation (304)
  // costs a read and a hash, not a gzip of three.js. One weak tag stands for both encodings.
  const std::string tag = entityTag(body);
  res.set_header("ETag", tag);
  res.set_header("Cache-Control", "no-cache");  // revalidated: a rebuilt page shows at once
  if (req.has_header("If-None-Match") && ifNoneMatchHits(req.get_header_value("If-None-Match"), tag)) {
    res.status = 304;
    return;
  }
  res.status = 200;
  const auto endsWith = [&](const char* suffix) {
    const size_t n = std::strlen(suffix);
    return relative.size() >= n && relative.compare(relative.size() - n, n, suffix) == 0;
  };
  if (endsWith(".js")) {
    if (acceptsGzip(req.get_header_value("Accept-Encoding"))) {
      body = gzipBody(body);
      res.set_header("Content-Encoding", "gzip");
    }
    res.set_header("Vary", "Accept-Encoding");
    res.set_content(std::move(body), "application/x-javascript");
  } else {
    res.set_content(std::move(body), endsWith(".css")    ? "text/css"
                                     : endsWith(".html") ? "text/html; charset=utf-8"
                                                         : "application/octet-stream");
  }
}

// cpp-httplib's request processing without its accept loop: the connection front reads each
// request first (server/http/connection_front.h) and hands it here on a worker.
class FrontedServer : public httplib::Server {
 public:
  bool serveOne(httplib::Stream& stream, bool closeConnection, bool& connectionClosed) {
    return process_request(stream, closeConnection, connectionClosed, nullptr);
  }
  // The bound socket, which the front owns from now on (cpp-httplib forgets it).
  int releaseListenSocket() { return static_cast<int>(svr_sock_.exchange(INVALID_SOCKET)); }
};

// The workers, counting the requests that wait for one (fsdb_http_connections_queued).
class CountingPool : public httplib::TaskQueue {
 public:
  CountingPool(size_t threads, std::atomic<int>* queued) : pool_(threads), queued_(queued) {}
  void enqueue(std::function<void()> fn) override {
    ++*queued_;
    pool_.enqueue([fn = std::move(fn), queued = queued_] {
      --*queued;
      fn();
    });
  }
  void shutdown() override { pool_.shutdown(); }

 private:
  httplib::ThreadPool pool_;
  std::atomic<int>* queued_;
};

void sendError(httplib::Response& res, const Error& e) {
  tErrorCode = e.code();
  // The memory budget is spent for now (server/service/memory_budget.h): say when to come back.
  if (e.code() == errc::kOverloaded) res.set_header("Retry-After", std::to_string(kOverloadedRetrySeconds));
  sendJson(res, httpStatusFor(e.code()), errorBody(e.code(), e.what(), e.path()));
}

}  // namespace

std::string ApiRequest::queryParam(const std::string& name) const {
  return raw.has_param(name.c_str()) ? raw.get_param_value(name.c_str()) : std::string();
}

bool ApiRequest::hasQueryParam(const std::string& name) const { return raw.has_param(name.c_str()); }

std::optional<std::string> ApiRequest::header(const std::string& name) const {
  if (!raw.has_header(name.c_str())) return std::nullopt;
  return raw.get_header_value(name.c_str());
}

HttpServer::HttpServer(ServerOptions options)
    : options_(std::move(options)), server_(std::make_unique<FrontedServer>()) {
  installHandlers();
}

HttpServer::~HttpServer() = default;

void HttpServer::addRoute(const std::string& method, const std::string& openapiPath, ApiHandler handler,
                          RouteOptions routeOptions) {
  routes_.push_back({method, openapiPath});
  routeWrites_.push_back(routeOptions.write);
  routePatterns_.emplace_back(routeRegex(openapiPath));
  const int maxDepth = options_.limits.maxJsonDepth;
  const size_t maxBody = options_.limits.maxBodyBytes;
  const std::string token = routeOptions.write ? options_.token : std::string();
  // POST and PUT bodies are read here through httplib's ContentReader, not by httplib itself:
  // httplib parses a body sent as application/x-www-form-urlencoded (curl -d's default) as a
  // form and answers 413 when it is over 8 KiB, so every JSON document over 8 KiB sent with
  // `curl -d` was refused as "larger than max_body_bytes". It also does not bound chunked bodies;
  // readBody does. (httplib still refuses a Content-Length over max_body_bytes first.)
  auto route = std::make_shared<const std::string>(openapiPath);
  std::atomic<int>* heavy = routeOptions.heavy ? &heavy_ : nullptr;
  const int maxHeavy = std::max(1, workerThreads_ / 2);
  auto wrapped = [handler = std::move(handler), maxDepth, maxBody, token, routeOptions, route, heavy, maxHeavy](
                     const httplib::Request& req, httplib::Response& res, const httplib::ContentReader* content) {
    tRoute = route.get();
    ApiRequest api{req, nullptr, {}, {}};
    struct HeavySlot {
      std::atomic<int>* count;
      ~HeavySlot() {
        if (count) --*count;
      }
    } slot{nullptr};
    try {
      if (heavy) {
        if (++*heavy > maxHeavy) {
          --*heavy;
          if (content) drainUnauthorizedBody(*content);  // not wanted: dropped, never kept
          throw Error(errc::kOverloaded,
                      "the server is building " + std::to_string(maxHeavy) +
                          " grids or meshes, the most it takes at once (half its --threads workers, so that other "
                          "requests always find one); retry in a few seconds",
                      "");
        }
        slot.count = heavy;
      }
      // The whole body first, as httplib did before any handler ran, so that an early error
      // never leaves unread bytes on a keep-alive connection.
      // The token before the body: an unauthenticated client's body is never read whole.
      if (!token.empty() && !bearerMatches(req.get_header_value("Authorization"), token)) {
        if (content) drainUnauthorizedBody(*content);
        res.set_header("WWW-Authenticate", "Bearer");
        throw unauthorizedError();
      }
      if (content) readBody(req, *content, maxBody, &api.bodyBytes, res);
      for (size_t i = 1; i < req.matches.size(); ++i) api.pathParams.push_back(req.matches[i].str());
      if (content && !routeOptions.rawBody) api.body = parseJsonBody(api.bodyBytes, maxDepth);
      ApiResponse out = handler(api);
      for (const auto& [name, value] : out.headers) res.set_header(name, value);
      if (out.contentType.empty()) {
        sendJson(res, out.status, out.json);
      } else {
        res.status = out.status;
        res.set_content(out.rawBody, out.contentType.c_str());
      }
      if (req.method == "GET" && res.status == 200) conditionalAndEncoded(req, res);
    } catch (const Error& e) {
      if (e.code() == errc::kStorage) warnStorageFailure(req, e);
      sendError(res, e);
    }
    // Anything else propagates to the exception handler: a 500 with a JSON body.
  };
  const std::string pattern = routeRegex(openapiPath);
  auto withoutBody = [wrapped](const httplib::Request& req, httplib::Response& res) { wrapped(req, res, nullptr); };
  auto withBody = [wrapped](const httplib::Request& req, httplib::Response& res,
                            const httplib::ContentReader& content) { wrapped(req, res, &content); };
  if (method == "GET") server_->Get(pattern, withoutBody);
  else if (method == "POST") server_->Post(pattern, withBody);
  else if (method == "PUT") server_->Put(pattern, withBody);
  else if (method == "DELETE") server_->Delete(pattern, withoutBody);
  else throw std::logic_error("unsupported method " + method);
}

void HttpServer::installHandlers() {
  auto& s = *server_;
  s.set_payload_max_length(options_.limits.maxBodyBytes);
  // httplib's default sets SO_REUSEPORT, which lets a second fsdb bind the same port and
  // silently share its traffic. SO_REUSEADDR alone allows a quick restart after a stop but
  // makes a port in use an error (tests/server/http/service_test: RefusesAPortInUse).
  // TCP_NODELAY (inherited by accepted sockets): httplib writes headers and body separately, and
  // Nagle's algorithm with the client's delayed ACK then adds ~40 ms to every keep-alive request
  // (bench/bench_get_part.sh: 75 requests/s without it).
  s.set_socket_options([this](socket_t sock) {
    listenSocket_ = static_cast<int>(sock);  // the listening socket (bind() widens its backlog)
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<const void*>(&yes), sizeof(yes));
    setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, reinterpret_cast<const void*>(&yes), sizeof(yes));
  });
  // At least 16. Workers take whole requests from the connection front, so idle and slow
  // connections hold none; half of them at most serve grid builds and meshes
  // (RouteOptions::heavy), so 16 evaluations at once leave 8 workers for everything else. (32
  // workers by default made the soak's RSS grow past its bound after the warm-up: each thread's
  // stack and heap warm up as it first serves.) 16 clients of POST /query/linguistic at 1M parts
  // had a p99 of 58-64 ms with 8 workers and 51-54 ms with 16, at the same throughput
  // (docs/performance.md). The store's connection pool, not the workers, bounds the database
  // work in flight.
  const int threads = options_.threads > 0 ? options_.threads : std::max(16u, std::thread::hardware_concurrency());
  workerThreads_ = threads;
  s.new_task_queue = [this, threads] { return new CountingPool(static_cast<size_t>(threads), &queued_); };
  // As many requests a connection as the front serves (FrontOptions::maxRequestsPerConnection),
  // named in each answer's Keep-Alive header.
  s.set_keep_alive_max_count(static_cast<size_t>(FrontOptions{}.maxRequestsPerConnection));

  if (!options_.corsOrigin.empty()) {
    // Every answer, errors included, names the origin; a preflight is answered for any path.
    s.set_default_headers({{"Access-Control-Allow-Origin", options_.corsOrigin},
                           {"Vary", "Origin"},
                           {"Access-Control-Expose-Headers", "ETag, Location, Content-Disposition, X-Fsdb-Cache"}});
    s.Options(".*", [](const httplib::Request&, httplib::Response& res) {
      res.status = 204;
      res.set_header("Access-Control-Allow-Methods", "GET, POST, PUT, DELETE, OPTIONS");
      res.set_header("Access-Control-Allow-Headers", "Content-Type, Authorization, If-None-Match, If-Match");
      res.set_header("Access-Control-Max-Age", "600");
    });
  }

  // The studio page: its own paths only (/, the page's files, /modules/..., /vendor/...), so no
  // API path is shadowed. Not cpp-httplib's mount point: that compresses JavaScript with brotli at its
  // highest quality on every request (seconds for three.js); here scripts go out gzipped once
  // (as application/x-javascript, a JavaScript type httplib leaves alone) and the small text
  // files as httplib encodes them.
  if (!options_.webRoot.empty()) {
    if (!std::filesystem::is_directory(options_.webRoot))
      spdlog::warn("no studio page: '{}' is not a folder (fsdb serve --web DIR)", options_.webRoot);
    else
      s.Get(kStudioPaths,
            [root = options_.webRoot](const httplib::Request& req, httplib::Response& res) {
              serveStatic(root, req, res);
            });
  }

  // Expect: 100-continue: a write without the token is refused before its body is sent. The front
  // answers 100 Continue itself to the requests this allows (mayContinue); the rest come here.
  if (!options_.token.empty()) {
    s.set_expect_100_continue_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (mayContinue(req.method, req.path, req.get_header_value("Authorization"))) return 100;
      res.set_header("WWW-Authenticate", "Bearer");
      sendError(res, unauthorizedError());
      return res.status;
    });
  }

  // No route takes PATCH. Left to httplib, a PATCH without Content-Length waited 5 s for a body
  // to its end and was then 400; here any body it announces is read and dropped (so the
  // connection stays in step), and the answer is 405 with the path's methods, or 404.
  s.Patch(".*", [this](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& content) {
    if (req.has_header("Content-Length") || req.has_header("Transfer-Encoding"))
      content([](const char*, size_t) { return true; });
    if (!refuseMethod(req.method, req.path, res)) res.status = 404;
  });

  s.set_pre_routing_handler([this](const httplib::Request&, httplib::Response&) {
    // A request whose answer could not be written never reached the logger: it is over now.
    if (tRequestStart != std::chrono::steady_clock::time_point{}) --inFlight_;
    tRequestStart = std::chrono::steady_clock::now();
    tRoute = nullptr;
    tErrorCode.clear();
    ++inFlight_;
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // Called for every status >= 400 whose body is still empty: unknown routes, wrong methods and
  // bodies over the limit, which httplib answers before any handler runs.
  s.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    if (res.status == 413) {
      sendError(res, Error(errc::kLimitExceeded,
                           "request body larger than max_body_bytes=" + std::to_string(options_.limits.maxBodyBytes),
                           "body"));
      return;
    }
    if (res.status == 414) {
      sendError(res, Error(errc::kLimitExceeded,
                           "request line longer than " + std::to_string(CPPHTTPLIB_REQUEST_URI_MAX_LENGTH) +
                               " bytes (the server's URI limit); send long texts in a POST body",
                           "uri"));
      res.status = 414;  // limit_exceeded is 413 for bodies; this limit has its own status
      return;
    }
    if (res.status == 400) {
      // httplib answers 400 before routing for a method it does not know (PROPFIND); where the
      // path has routes, that is 405 with the methods it has. req.path is not parsed yet then:
      // the target up to its query.
      if (refuseMethod(req.method, req.path.empty() ? req.target.substr(0, req.target.find('?')) : req.path, res))
        return;
      sendError(res, Error("bad_request",
                           "malformed HTTP request: a request or header line longer than " +
                               std::to_string(CPPHTTPLIB_HEADER_MAX_LENGTH) +
                               " bytes, a POST or PUT without a body or Content-Length where no route takes one, "
                               "or not HTTP/1.x",
                           ""));
      return;
    }
    if (res.status == 404) {
      if (refuseMethod(req.method, req.path, res)) return;
      sendError(res,
                Error(errc::kNotFound,
                      "no endpoint " + req.method + " " + req.path + "; GET /openapi.json lists every endpoint", ""));
      return;
    }
    sendJson(res, res.status, errorBody("http_" + std::to_string(res.status), "request failed", ""));
  });

  s.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown exception";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    spdlog::error("{} {}: internal error: {}", req.method, req.path, what);
    sendJson(res, 500, errorBody("internal", "internal error: " + what, ""));
  });

  s.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - tRequestStart).count();
    spdlog::info("{} {} {} {}B {:.2f}ms", req.method, req.path, res.status, res.body.size(), ms);
    // Requests that passed the pre-routing handler (those httplib refused before it are not
    // logged either). Their series: the route's template, "page" or "none".
    if (tRequestStart != std::chrono::steady_clock::time_point{}) {
      --inFlight_;
      static const std::string page = "page", none = "none";
      const std::string& route = tRoute ? *tRoute : (!options_.webRoot.empty() && isStudioPath(req.path) ? page : none);
      // One step: GET /metrics never sees the request without its refusal (a test read between
      // the two once: the 404 counted, its not_found not yet).
      metrics_.observe(req.method, route, res.status, ms / 1000.0, tErrorCode);
      tRequestStart = {};
    }
  });
}

bool HttpServer::refuseMethod(const std::string& method, const std::string& path, httplib::Response& res) const {
  const std::string allow = method.empty() ? std::string() : allowedMethods(path);
  if (allow.empty() || (", " + allow + ", ").find(", " + method + ", ") != std::string::npos) return false;
  res.set_header("Allow", allow);
  // Both echoed: cut, so that a long method or path cannot make a long answer.
  sendError(res, Error("method_not_allowed",
                       method.substr(0, 32) + " is not allowed on " + path.substr(0, 200) + "; allowed: " + allow, ""));
  return true;
}

std::string HttpServer::allowedMethods(const std::string& path) const {
  std::vector<std::string> allowed;
  const auto add = [&allowed](const std::string& method) {
    if (std::find(allowed.begin(), allowed.end(), method) == allowed.end()) allowed.push_back(method);
  };
  for (size_t i = 0; i < routes_.size(); ++i)
    if (std::regex_match(path, routePatterns_[i])) add(routes_[i].method);
  if (!options_.webRoot.empty() && isStudioPath(path)) add("GET");
  std::string allow;
  for (const auto& m : allowed) allow += (allow.empty() ? "" : ", ") + m;
  return allow;
}

bool validCorsOrigin(const std::string& origin) {
  static const std::regex form("https?://[A-Za-z0-9.-]+(:[0-9]{1,5})?");
  return origin == "*" || std::regex_match(origin, form);
}

int HttpServer::bind() {
  int port = options_.port;
  if (port == 0) {
    port = server_->bind_to_any_port(options_.host);
    if (port < 0) throw std::runtime_error("cannot bind " + options_.host + " on any port");
  } else if (!server_->bind_to_port(options_.host, port)) {
    throw std::runtime_error("cannot bind " + options_.host + ":" + std::to_string(port) +
                             " (in use, or not an address of this machine); try --port 0");
  }
  // httplib listens with a backlog of 5: 64 clients reconnecting at once overflowed it, and the
  // connections beyond the queue were dropped and retried by the client's kernel after 1 s
  // (bench/soak.sh: wrk timeouts, 1.1 s latencies, a reset). A second listen() on the bound
  // socket sets the kernel's largest queue instead.
  if (listenSocket_ >= 0 && ::listen(listenSocket_, SOMAXCONN) != 0)
    spdlog::warn("cannot widen the listen backlog: {}", std::strerror(errno));
  return port;
}

bool HttpServer::mayContinue(const std::string& method, const std::string& path,
                              const std::string& authorization) const {
  if (options_.token.empty()) return true;
  bool write = false;
  for (size_t i = 0; i < routes_.size() && !write; ++i)
    write = routeWrites_[i] && routes_[i].method == method && std::regex_match(path, routePatterns_[i]);
  return !write || bearerMatches(authorization, options_.token);
}

int HttpServer::connectionsOpen() const {
  const ConnectionFront* front = front_.load();
  return front ? front->openConnections() : 0;
}

void HttpServer::listen() {
  if (!stopRequested_.load()) {
    std::unique_ptr<httplib::TaskQueue> workers(server_->new_task_queue());
    FrontOptions frontOptions;
    frontOptions.readTimeoutMs = options_.readTimeoutMs;
    frontOptions.refused = [this](const std::string& code) { metrics_.reject(code); };
    auto* server = static_cast<FrontedServer*>(server_.get());
    listenSocket_ = -1;
    ConnectionFront front(
        server->releaseListenSocket(), frontOptions, *workers,
        [server](httplib::Stream& stream, bool close, bool& closed) { return server->serveOne(stream, close, closed); },
        [this](const RequestHead& head) {
          return mayContinue(head.method, head.path(), head.header("Authorization"));
        });
    {
      std::lock_guard<std::mutex> lock(frontMutex_);
      front_.store(&front);
    }
    // stop() may have come between the check above and front_ being set: it waits for one or the other.
    if (stopRequested_.load()) front.stop();
    front.run();
    workers->shutdown();
    std::lock_guard<std::mutex> lock(frontMutex_);  // no stop() holds the front while it ends
    front_.store(nullptr);
  }
  listenReturned_.store(true);
}

void HttpServer::stop() {
  stopRequested_.store(true);
  // A SIGTERM right after the port line (before listen() started) must not be lost: listen()
  // checks stopRequested_ first, so wait until it either serves (then the front's stop() ends it)
  // or has returned.
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(frontMutex_);
      if (ConnectionFront* front = front_.load()) {
        front->stop();
        return;
      }
    }
    if (listenReturned_.load()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace fsdb
