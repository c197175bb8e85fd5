// The fsdb executable: `fsdb serve`, `fsdb import`, `fsdb eval`, `fsdb query` (docs/api.md §1).
#include <CLI/CLI.hpp>
#include <httplib.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <pthread.h>
#include <algorithm>
#include <thread>

#include "fsdb_version.h"
#include "db/store.h"
#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/memory_budget.h"
#include "server/http/api.h"
#include "server/service/bulk_import.h"
#include "server/service/descriptor_rows.h"
#include "server/cli/allocator.h"
#include "server/cli/eval_command.h"
#include "server/cli/log_sink.h"
#include "server/cli/file_io.h"
#include "server/http/http_server.h"
#include "server/cli/import_command.h"
#include "server/cli/query_command.h"

namespace {

// SIGINT/SIGTERM are blocked in every thread and received by one waiter thread, which asks the
// server to stop: httplib then finishes in-flight requests and listen() returns (graceful stop).
void blockShutdownSignals(sigset_t* set) {
  sigemptyset(set);
  sigaddset(set, SIGINT);
  sigaddset(set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, set, nullptr);
}

// The demo catalogue (docs/api.md §1): every *.jsonl of `dir` in name order, upserted, into a
// database that was just created. Failures are logged, never fatal: the server still starts.
void loadDemo(fsdb::Store& store, const std::string& dir, const fsdb::DocumentLimits& limits) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".jsonl") files.push_back(entry.path());
  if (ec) {
    spdlog::warn("demo catalogue {}: {}", dir, ec.message());
    return;
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    fsdb::BulkOptions bulk;
    bulk.mode = fsdb::BulkMode::kUpsert;
    bulk.limits = limits;
    try {
      const fsdb::BulkReport r = fsdb::importBody(store, fsdb::readTextFile(f.string(), "--demo"), fsdb::kFileJsonDepth, bulk);
      spdlog::info("demo catalogue {}: imported {}, failed {}", f.string(), r.imported, r.failed);
      for (const auto& e : r.errors) spdlog::warn("demo {}:{}: {}", f.string(), e["line"].dump(), e["error"].dump());
    } catch (const fsdb::Error& e) {
      spdlog::warn("demo catalogue {}: {}", f.string(), e.what());
    }
  }
}

// Objects without fresh descriptor rows (a database older than migration 002, or a process that
// stopped between a write and its refresh) are searched from their documents until this runs.
void backfillDescriptorIndex(fsdb::Store& store, size_t maxNodes) {
  const auto start = std::chrono::steady_clock::now();
  const size_t n = fsdb::refreshPendingDescriptors(store, maxNodes);
  if (n == 0) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("descriptor index: backfilled {} objects in {:.2f} s", n, seconds);
}

// --vocabulary FILE of serve, eval and query: makes the file the active vocabulary (every parser
// reads it) before anything is parsed. False, with the message on the log, when the file is bad.
bool useVocabulary(const std::string& vocabularyPath) {
  if (vocabularyPath.empty()) return true;
  try {
    fsdb::setActiveVocabulary(fsdb::Vocabulary::fromFile(vocabularyPath));
    spdlog::info("vocabulary {}", vocabularyPath);
    return true;
  } catch (const fsdb::Error& e) {
    spdlog::error("cannot load the vocabulary: {} (at {})", e.what(), e.path().empty() ? "the top" : e.path());
    return false;
  }
}

int runServe(const fsdb::ServerOptions& options, const std::string& dbPath, const std::string& demoDir) {
  sigset_t signals;
  blockShutdownSignals(&signals);  // before any thread exists, so all inherit the mask
  // A client that hangs up while its answer is written must cost that request, not the server.
  std::signal(SIGPIPE, SIG_IGN);
  // Before the worker threads exist: their arenas follow it (server/cli/allocator.h).
  spdlog::info("allocator: {}", fsdb::tuneAllocatorForServing(std::thread::hardware_concurrency()).description);

  std::unique_ptr<fsdb::Store> store;
  try {
    fsdb::StoreOptions storeOptions;
    storeOptions.maxCacheBytes = options.maxCacheMb << 20;
    store = fsdb::Store::open(dbPath, storeOptions);
    spdlog::info("database {} on {} (schema version {})", store->path(), store->backend(), store->schemaVersion());
    // A database never written to gets the demo (loaded by upsert: two servers starting on one new
    // PostgreSQL database both load it, and the second changes nothing).
    const bool fresh = store->changeSeq() == 0 && store->counts().empty();
    if (fresh && !demoDir.empty()) loadDemo(*store, demoDir, fsdb::documentLimits(options.limits));
    backfillDescriptorIndex(*store, options.limits.maxNodes);
  } catch (const fsdb::Error& e) {
    spdlog::error("cannot open the database: {}", e.what());
    return 1;
  }
  fsdb::HttpServer server(options);
  fsdb::registerAllRoutes(server, *store);
  int port = 0;
  try {
    port = server.bind();
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  // docs/api.md §1: the first line on stdout; scripts and tests read the port from it.
  std::cout << "listening on http://" << options.host << ":" << port << std::endl;
  spdlog::info("fsdb {} serving {} routes, max body {} bytes", FSDB_VERSION, server.routes().size(),
               options.limits.maxBodyBytes);

  // The thumbnails, requested from this server's own routes (the same cache, limits and log as a
  // browser's requests) by one background client; requests wait until listen() starts.
  std::thread thumbnails;
  if (options.warmThumbnails) {
    std::vector<std::pair<std::string, int64_t>> objects;
    for (const char* kind : {"shape", "part"}) {
      fsdb::ListQuery query;
      query.kind = kind;
      query.limit = 1000;
      for (std::vector<fsdb::StoredObject> page; !(page = store->list(query)).empty(); query.afterId = page.back().id)
        for (const fsdb::StoredObject& o : page) objects.emplace_back(kind, o.id);
    }
    thumbnails = std::thread([objects, port, host = options.host == "0.0.0.0" ? std::string("127.0.0.1") : options.host]() {
      httplib::Client client(host, port);
      client.set_read_timeout(120, 0);
      size_t drawn = 0;
      for (const auto& [kind, id] : objects) {
        auto r = client.Get(("/" + kind + "s/" + std::to_string(id) + "/thumbnail.png").c_str());
        if (!r) return;  // the server stopped
        if (r->status == 200 && r->get_header_value("X-Fsdb-Cache") == "miss") ++drawn;
      }
      spdlog::info("thumbnails: {} drawn, {} objects", drawn, objects.size());
    });
  }

  std::thread waiter([&server, signals]() {
    int sig = 0;
    sigwait(&signals, &sig);
    spdlog::info("received signal {}, finishing in-flight requests", sig);
    server.stop();
  });
  server.listen();
  // listen() can only return after stop(), which only the waiter calls.
  waiter.join();
  if (thumbnails.joinable()) thumbnails.join();  // its next request fails at once: the server is down
  try {
    store->checkpoint();  // the WAL folded into the main file: the .sqlite is whole on its own
  } catch (const fsdb::Error& e) {
    spdlog::warn("checkpoint at shutdown: {}", e.what());
  }
  spdlog::info("stopped");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  fsdb::installLogger();
  // Writes the buffered log lines however main returns (CLI11_PARSE returns from inside).
  struct LogShutdown {
    ~LogShutdown() { spdlog::shutdown(); }
  } logShutdown;

  CLI::App app{"fsdb: a fuzzy shape database server"};
  app.set_version_flag("--version", FSDB_VERSION);
  app.require_subcommand(1);
  std::string logLevel = "info";
  app.add_option("--log-level", logLevel, "trace, debug, info, warn, error, off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

  fsdb::ServerOptions serve;
  std::string dbPath = "data/fsdb.sqlite", demoDir;
  std::string vocabularyPath;  // --vocabulary of serve, eval and query (one subcommand runs)
  if (const char* t = std::getenv("FSDB_TOKEN")) serve.token = t;
  auto* serveCmd = app.add_subcommand("serve", "serve the HTTP API");
  serveCmd->add_option("--db", dbPath,
                       "SQLite database file (created with its directory if missing), or a PostgreSQL URL "
                       "postgresql://user@host:port/database[?schema=NAME] shared by several servers")
      ->capture_default_str();
  serveCmd->add_option("--vocabulary", vocabularyPath,
                       "a vocabulary file (the format of schema/vocabulary.json) instead of the built-in one");
  serveCmd->add_option("--demo", demoDir, "load DIR/*.jsonl when the database file is created by this start");
  serveCmd->add_option("--token", serve.token, "require 'Authorization: Bearer TOKEN' for writes (or FSDB_TOKEN)");
  serveCmd->add_option("--host", serve.host, "address to bind")->capture_default_str();
  serveCmd->add_option("--port", serve.port, "port; 0 picks a free one")
      ->check(CLI::Range(0, 65535))->capture_default_str();
  serveCmd->add_option("--threads", serve.threads, "worker threads; 0 = number of cores, at least 16 (half of them at most build grids and meshes)")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  serveCmd->add_option("--max-body-bytes", serve.limits.maxBodyBytes, "largest accepted request body")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-json-depth", serve.limits.maxJsonDepth, "deepest accepted JSON nesting")
      ->check(CLI::Range(2, 10000))->capture_default_str();
  serveCmd->add_option("--max-points", serve.limits.maxPoints, "points per POST /operators/evaluate")
      ->check(CLI::PositiveNumber)->capture_default_str();

  serveCmd->add_option("--max-resolution", serve.limits.maxResolution, "largest grid resolution of POST /evaluate")
      ->check(CLI::Range(2, 4096))->capture_default_str();
  serveCmd->add_option("--max-grid-mb", serve.limits.maxGridMb,
                       "most MiB of voxel blocks in one evaluation's grid (POST /evaluate, stored-shape evaluate, "
                       "mesh and grid.vdb; 413 beyond); 0: no limit")
      ->check(CLI::Range(0, 1 << 24))->capture_default_str();
  serveCmd->add_option("--max-eval-ms", serve.limits.maxEvalMs,
                       "longest evaluation in milliseconds (POST /evaluate, stored-shape evaluate, mesh and grid.vdb; "
                       "413 beyond); 0: no limit")
      ->check(CLI::Range(0, 86400000))->capture_default_str();
  serveCmd->add_option("--max-bulk-errors", serve.limits.maxBulkErrors,
                       "failed lines listed in a bulk import's answer (the rest counted; errors_truncated)")
      ->check(CLI::Range(size_t(0), size_t(1000000)))->capture_default_str();
  serveCmd->add_option("--max-nodes", serve.limits.maxNodes, "most CSG nodes in one shape")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-control-points", serve.limits.maxControlPoints,
                       "most control points of a Bezier curve or surface grid (requests, stored documents, exports)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-curve-points", serve.limits.maxCurvePoints,
                       "most evaluation points (u values, uv pairs, export samples) per Bezier request")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-fair-points", serve.limits.fairCurve.maxPoints,
                       "most given points of a fair curve (POST /curves/fair, stored fair curves)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-fair-samples", serve.limits.fairCurve.maxSamples, "most curve points per fair-curve piece")
      ->check(CLI::Range(2, 1000000))->capture_default_str();
  serveCmd->add_option("--max-fair-angle-samples", serve.limits.fairCurve.maxAngleSamples,
                       "most samples of a fair-curve point's fuzzy set over [0, 180) degrees")
      ->check(CLI::Range(4, 1000000))->capture_default_str();
  serveCmd->add_option("--max-fair-candidates", serve.limits.fairCurve.maxCandidates,
                       "most candidate curves of one fair-curve answer")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-fair-curve-points", serve.limits.fairCurve.maxCurvePoints,
                       "most curve points (candidates x pieces x samples) of one fair-curve answer")
      ->check(CLI::PositiveNumber)->capture_default_str();
#ifdef FSDB_WEB_DIR
  serve.webRoot = FSDB_WEB_DIR;  // the build's studio page (web/build-web)
#endif
  serveCmd->add_option("--web", serve.webRoot, "the studio page's folder, served at / (default: the build's)")
      ->capture_default_str();
  serveCmd->add_flag("--warm-thumbnails", serve.warmThumbnails,
                     "draw every stored object's thumbnail in the background after the start (the studio's first view)");
  serveCmd->add_option("--cors", serve.corsOrigin,
                       "allow pages from ORIGIN (http(s)://host[:port], or *) to call the API; off by default")
      ->check([](const std::string& origin) {
        return fsdb::validCorsOrigin(origin) ? std::string()
                                             : "--cors takes an origin such as http://localhost:5173 (scheme, host, "
                                               "optional port, no path) or *; got '" + origin + "'";
      });
  serveCmd->add_flag_callback("--no-warm-graphs", [&serve]() { serve.warmGraphs = false; },
                              "do not build the graphs of structural search at start (the first query does)");
  serve.limits.maxMemoryMb = fsdb::MemoryBudget::defaultLimitBytes() >> 20;
  serveCmd->add_option("--max-memory-mb", serve.limits.maxMemoryMb,
                       "MiB that all evaluations and meshes may hold at once (503 overloaded beyond); "
                       "default: half the machine's memory; 0: no limit")
      ->check(CLI::Range(std::uint64_t(0), std::uint64_t(1) << 40))->capture_default_str();
  serveCmd->add_option("--max-cache-mb", serve.maxCacheMb,
                       "MiB of cached evaluations and exports (least recently used evicted first); 0: no limit")
      ->check(CLI::Range(std::uint64_t(0), std::uint64_t(1) << 40))->capture_default_str();
  serveCmd->add_option("--read-timeout-ms", serve.readTimeoutMs,
                       "a request's head and its body's first MiB must arrive within this from its first byte "
                       "(the body at 64 KiB/s more); 408 beyond")
      ->check(CLI::Range(100, 3600000))->capture_default_str();
  serveCmd->add_option("--max-query-ms", serve.limits.maxQueryMs,
                       "longest POST /query/linguistic or /query/csg search in milliseconds (413 beyond); 0: no limit")
      ->check(CLI::Range(0, 86400000))->capture_default_str();
  serveCmd->add_option("--max-csg-pairs", serve.limits.maxCsgPairs,
                       "most query leaves x stored leaves of one POST /query/csg match (413 beyond)")
      ->check(CLI::PositiveNumber)->capture_default_str();

  std::string evalFile;
  fsdb::EvalOptions eval;
  auto* evalCmd = app.add_subcommand("eval", "evaluate a shape or part document (JSON file, - for stdin) on a voxel grid");
  evalCmd->add_option("SHAPE-ID|FILE", evalFile,
                      "a stored shape's id (with --db), or a file: {\"kind\":\"part\"|\"shape\",...} or a POST /evaluate request")
      ->required();
  evalCmd->add_option("--resolution", eval.resolution, "voxels along the longest side")->check(CLI::Range(2, 4096));
  evalCmd->add_option("--alphas", eval.alphas, "levels, comma separated")->delimiter(',');
  evalCmd->add_option("--mesh", eval.meshPath,
                      "write the surface of lower/upper(alpha) to OUT.obj or OUT.stl, or both to OUT.glb");
  evalCmd->add_option("--mesh-alpha", eval.meshAlpha, "the level of --mesh")->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  evalCmd->add_option("--mesh-bound", eval.meshBound, "lower or upper")
      ->check(CLI::IsMember({"lower", "upper"}))->capture_default_str();
  evalCmd->add_option("--vdb", eval.vdbPath, "write both grids (upper, lower) to OUT.vdb");

  evalCmd->add_option("--max-grid-mb", eval.maxGridMb, "stop when the grid's voxel blocks pass this many MiB; 0: no limit")
      ->check(CLI::Range(0, 1 << 24))->capture_default_str();
  evalCmd->add_option("--max-eval-ms", eval.maxEvalMs, "stop an evaluation running longer (milliseconds); 0: no limit")
      ->check(CLI::Range(0, 86400000))->capture_default_str();
  evalCmd->add_option("--db", eval.dbPath, "database (file or PostgreSQL URL) for SHAPE-ID and for references in FILE");
  evalCmd->add_option("--vocabulary", vocabularyPath, "a vocabulary file for parts described by words (as for serve)");

  fsdb::ImportOptions import;
  import.dbPath = dbPath;
  if (const char* t = std::getenv("FSDB_TOKEN")) import.token = t;
  auto* importCmd = app.add_subcommand("import", "bulk import of JSON Lines files of part and shape documents");
  importCmd->add_option("FILE", import.files, "JSON Lines files (or files holding one JSON array)")->required();
  auto* importDb = importCmd->add_option("--db", import.dbPath, "database file or PostgreSQL URL")->capture_default_str();
  importCmd->add_option("--server", import.serverUrl, "import through a running server, e.g. http://127.0.0.1:8080")
      ->excludes(importDb);
  importCmd->add_option("--token", import.token, "bearer token for --server (or FSDB_TOKEN)");
  importCmd->add_option("--mode", import.mode, "create: a taken name is an error; upsert: it gets a new version")
      ->check(CLI::IsMember({"create", "upsert"}))->capture_default_str();
  importCmd->add_option("--batch", import.batchSize, "lines per transaction")->check(CLI::Range(1, 10000))
      ->capture_default_str();
  importCmd->add_option("--max-errors", import.maxErrors, "failed lines listed per file (the rest are counted)")
      ->check(CLI::Range(size_t(0), size_t(100000000)))->capture_default_str();

  fsdb::QueryCommandOptions query;
  query.dbPath = dbPath;
  auto* queryCmd = app.add_subcommand("query", "linguistic search (\"find a slightly bent shape\") or CSG search (\"a cube minus a cylinder\", \"A + B - C\") (exit 0 ran, 1 refused, 2 no database or server)");
  queryCmd->add_option("TEXT", query.text, "the query in words (GET /vocabulary lists them) or a CSG text (schema/csg_query_grammar.ebnf)")->required();
  auto* queryDb = queryCmd->add_option("--db", query.dbPath, "database file or PostgreSQL URL")->capture_default_str();
  queryCmd->add_option("--server", query.serverUrl, "ask a running server, e.g. http://127.0.0.1:8080")->excludes(queryDb);
  queryCmd->add_option("--limit", query.limit, "most results")->check(CLI::Range(1, 1000))->capture_default_str();
  queryCmd->add_option("--threshold", query.threshold, "least score")->check(CLI::Range(0.0, 1.0))->capture_default_str();
  queryCmd->add_option("--kind", query.kind, "linguistic: only parts or only shapes")->check(CLI::IsMember({"part", "shape"}));
  queryCmd->add_flag("--scan", query.scan, "linguistic: score every object instead of the index's candidates (same results)");
  queryCmd->add_flag("--json", query.json, "print the JSON answer of POST /query/linguistic or /query/csg");
  queryCmd->add_option("--vocabulary", vocabularyPath, "with --db: a vocabulary file instead of the built-in one (as for serve)")
      ->excludes("--server");

  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::from_str(logLevel));

  // Before the demo is loaded and anything parsed: every parser reads the active vocabulary.
  if (!useVocabulary(vocabularyPath)) return 1;
  if (serveCmd->parsed()) return runServe(serve, dbPath, demoDir);
  if (evalCmd->parsed()) return fsdb::runEval(evalFile, eval);
  if (importCmd->parsed()) return fsdb::runImport(import);
  if (queryCmd->parsed()) return fsdb::runQuery(query);
  return 2;
}
