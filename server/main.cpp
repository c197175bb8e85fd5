// The fsdb executable: `fsdb serve` (and, as their issues land, import / query / eval).
#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <csignal>
#include <iostream>
#include <pthread.h>
#include <thread>

#include "fsdb_version.h"
#include "server/api.h"
#include "server/eval_command.h"
#include "server/http_server.h"

namespace {

// SIGINT/SIGTERM are blocked in every thread and received by one waiter thread, which asks the
// server to stop: httplib then finishes in-flight requests and listen() returns (graceful stop).
void blockShutdownSignals(sigset_t* set) {
  sigemptyset(set);
  sigaddset(set, SIGINT);
  sigaddset(set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, set, nullptr);
}

int runServe(const fsdb::ServerOptions& options) {
  sigset_t signals;
  blockShutdownSignals(&signals);  // before any thread exists, so all inherit the mask

  fsdb::HttpServer server(options);
  fsdb::registerAllRoutes(server);
  int port = 0;
  try {
    port = server.bind();
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  // SPEC §1: the first line on stdout; scripts and tests read the port from it.
  std::cout << "listening on http://" << options.host << ":" << port << std::endl;
  spdlog::info("fsdb {} serving {} routes, max body {} bytes", FSDB_VERSION, server.routes().size(),
               options.limits.maxBodyBytes);

  std::thread waiter([&server, signals]() {
    int sig = 0;
    sigwait(&signals, &sig);
    spdlog::info("received signal {}, finishing in-flight requests", sig);
    server.stop();
  });
  server.listen();
  // listen() can only return after stop(), which only the waiter calls.
  waiter.join();
  spdlog::info("stopped");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_default_logger(spdlog::stderr_color_mt("fsdb"));
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");

  CLI::App app{"fsdb: a fuzzy shape database server"};
  app.set_version_flag("--version", FSDB_VERSION);
  app.require_subcommand(1);
  std::string logLevel = "info";
  app.add_option("--log-level", logLevel, "trace, debug, info, warn, error, off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

  fsdb::ServerOptions serve;
  auto* serveCmd = app.add_subcommand("serve", "serve the HTTP API");
  serveCmd->add_option("--host", serve.host, "address to bind")->capture_default_str();
  serveCmd->add_option("--port", serve.port, "port; 0 picks a free one")
      ->check(CLI::Range(0, 65535))->capture_default_str();
  serveCmd->add_option("--threads", serve.threads, "worker threads; 0 = number of cores")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  serveCmd->add_option("--max-body-bytes", serve.limits.maxBodyBytes, "largest accepted request body")
      ->check(CLI::PositiveNumber)->capture_default_str();
  serveCmd->add_option("--max-json-depth", serve.limits.maxJsonDepth, "deepest accepted JSON nesting")
      ->check(CLI::Range(2, 10000))->capture_default_str();
  serveCmd->add_option("--max-points", serve.limits.maxPoints, "points per POST /operators/evaluate")
      ->check(CLI::PositiveNumber)->capture_default_str();

  serveCmd->add_option("--max-resolution", serve.limits.maxResolution, "largest grid resolution of POST /evaluate")
      ->check(CLI::Range(2, 4096))->capture_default_str();
  serveCmd->add_option("--max-nodes", serve.limits.maxNodes, "most CSG nodes in one shape")
      ->check(CLI::PositiveNumber)->capture_default_str();

  std::string evalFile;
  fsdb::EvalOptions eval;
  auto* evalCmd = app.add_subcommand("eval", "evaluate a shape or part document (JSON file, - for stdin) on a voxel grid");
  evalCmd->add_option("FILE", evalFile, "the document: {\"kind\":\"part\"|\"shape\",...} or a POST /evaluate request")
      ->required();
  evalCmd->add_option("--resolution", eval.resolution, "voxels along the longest side")->check(CLI::Range(2, 4096));
  evalCmd->add_option("--alphas", eval.alphas, "levels, comma separated")->delimiter(',');
  evalCmd->add_option("--mesh", eval.meshPath, "write the surface of lower/upper(alpha) to OUT.obj or OUT.stl");
  evalCmd->add_option("--mesh-alpha", eval.meshAlpha, "the level of --mesh")->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  evalCmd->add_option("--mesh-bound", eval.meshBound, "lower or upper")
      ->check(CLI::IsMember({"lower", "upper"}))->capture_default_str();
  evalCmd->add_option("--vdb", eval.vdbPath, "write both grids (upper, lower) to OUT.vdb");

  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::from_str(logLevel));

  if (serveCmd->parsed()) return runServe(serve);
  if (evalCmd->parsed()) return fsdb::runEval(evalFile, eval);
  return 2;
}
