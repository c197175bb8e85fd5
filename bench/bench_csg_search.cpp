// Structural search speed: POST /query/csg's search (server/service/csg_search.h) over N stored
// trees, pruned (signature and matrix bounds) against unpruned (every tree matched), in one run.
// Goal: p50 < 200 ms at 10k trees with the stored graphs in memory (server/service/stored_graphs.h); the
// first query of a process (graphs built from the documents, in parallel) is reported apart as "cold",
// after the same build done serially ("cold serial build").
//
// Usage: bench_csg_search [--sizes 10000] [--dir DIR] [--reps R] [--full-reps S]
//                         [--benchmark_out=FILE.json] (other --benchmark_* flags are ignored)
// A catalogue is built once per size into DIR/csg-N.sqlite (default build/bench-data): random trees
// of 3 to 11 nodes (seeded) over inline parts from words (a dozen descriptions, some placed) and a
// pool of 200 stored parts, through prepareDocument and Store::createBatch as an import would.
// Every query runs R times pruned and S times unpruned; both answers must be equal.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_stats.h"
#include "db/store.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/csg_search.h"
#include "server/service/descriptor_rows.h"
#include "server/service/documents.h"

namespace {

using fsdb::bench::Clock;
using fsdb::bench::compareRuns;
using fsdb::bench::msSince;
using fsdb::bench::timeRuns;
using nlohmann::json;

const std::vector<std::string> kWords = {
    "a very bent cylinder", "a straight cylinder", "a very sharp pyramid", "a sphere",        "a box",
    "a slightly tapered cone", "a cube",           "a long rod",           "a flat disc",     "a twisted box",
    "a slightly bent rod",  "a very round box"};

int pick(std::mt19937& rng, int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }

json randomTree(std::mt19937& rng, int depth) {
  if (depth == 0 || pick(rng, 4) == 0) {
    if (pick(rng, 5) == 0) return {{"part", "part_" + std::to_string(1 + pick(rng, 200))}};
    json leaf = {{"part", {{"text", kWords[size_t(pick(rng, int(kWords.size())))]}}}};
    if (pick(rng, 4) == 0) leaf["transform"] = {{"translate", {pick(rng, 5), pick(rng, 5), 0}}};
    return leaf;
  }
  static const char* ops[] = {"union", "union", "intersection", "difference"};
  json children = json::array();
  for (int n = 2 + pick(rng, 2); n > 0; --n) children.push_back(randomTree(rng, depth - 1));
  return {{"op", ops[pick(rng, 4)]}, {"children", children}};
}

void build(const std::string& path, size_t n) {
  const std::string tmp = path + ".tmp";
  std::filesystem::remove(tmp);
  auto store = fsdb::Store::open(tmp);
  std::mt19937 rng(42);
  const auto start = Clock::now();
  std::vector<fsdb::NewObject> parts;
  for (int i = 1; i <= 200; ++i)
    parts.push_back(fsdb::prepareDocument({{"kind", "part"}, {"name", "part_" + std::to_string(i)},
                                           {"text", kWords[size_t(pick(rng, int(kWords.size())))]},
                                           {"params", {{"a2", 0.5 + 0.005 * i}}}},
                                          "part", *store, fsdb::DocumentLimits{}, ""));
  store->createBatch(parts, fsdb::BulkMode::kCreate);
  for (size_t done = 0; done < n;) {
    std::vector<fsdb::NewObject> items;
    for (size_t i = 0; i < 2000 && done < n; ++i, ++done) {
      json tree = randomTree(rng, 3);
      if (!tree.contains("op")) tree = {{"op", "union"}, {"children", {tree, randomTree(rng, 1)}}};
      items.push_back(fsdb::prepareDocument({{"kind", "shape"}, {"name", "tree-" + std::to_string(done + 1)}, {"tree", tree}},
                                            "shape", *store, fsdb::DocumentLimits{}, ""));
    }
    store->createBatch(items, fsdb::BulkMode::kCreate);
  }
  fsdb::refreshPendingDescriptors(*store, 10000);
  store->checkpoint();
  store.reset();
  std::filesystem::rename(tmp, path);
  std::fprintf(stderr, "built %s: %zu trees in %.1f s\n", path.c_str(), n, msSince(start) / 1000);
}

const std::vector<std::string> kQueries = {
    "the union of a very bent cylinder and a very sharp pyramid",
    "a cube minus a cylinder",
    "the intersection of a sphere and a box",
    "the union of a cube and the difference of a box and a slightly bent rod",
    "\"very bent cylinder\" + part_7 - sphere",
};

}  // namespace

int main(int argc, char** argv) {
  fsdb::bench::Args args;
  args.reps = 11, args.refReps = 3;
  if (!fsdb::bench::parseArgs(argc, argv, "--full-reps", args)) return 2;
  if (args.sizes.empty()) args.sizes = {10000};
  const std::string& dir = args.dir;
  const int reps = args.reps, fullReps = args.refReps;
  std::filesystem::create_directories(dir);
  return fsdb::bench::runReport("bench_csg_search", args.out, [&](json& report) {
    for (size_t n : args.sizes) {
      const std::string path = dir + "/csg-" + std::to_string(n) + ".sqlite";
      if (!std::filesystem::exists(path)) build(path, n);
      auto store = fsdb::Store::open(path);
      fsdb::StoredGraphCache cache;
      const fsdb::ReferenceResolver resolver = fsdb::storeResolver(*store);
      std::printf("== %zu trees (%s)\n", n, path.c_str());
      std::printf("%-75s %5s %7s %7s %8s %8s %9s %7s %6s\n", "query", "hits", "bounded", "matched", "p50 ms",
                  "p95 ms", "full ms", "ratio", "equal");
      for (const std::string& text : kQueries) {
        const fsdb::CsgQuery q = fsdb::parseCsgQuery(text, fsdb::Vocabulary::builtin(), resolver, 10000);
        fsdb::CsgSearchOptions options;
        options.limit = 10;
        if (cache.size() == 0) {
          {  // the serial build of every graph (one graph() call per shape), for the ratio to the parallel one
            fsdb::StoredGraphCache serial;
            const fsdb::StoreVersions versions = fsdb::StoreVersions::read(*store);
            const auto t = Clock::now();
            for (const fsdb::ObjectVersion& shape : versions.shapes) serial.graph(*store, shape, versions, 10000);
            std::printf("cold serial build (graphs of %zu trees, one at a time): %.0f ms\n", serial.size(), msSince(t));
            report.push_back({{"trees", n}, {"cold_serial_ms", msSince(t)}});
          }
          const auto t = Clock::now();
          fsdb::searchCsg(*store, q, options, cache);
          std::printf("cold (graphs of %zu trees built from their documents): %.0f ms\n", cache.size(), msSince(t));
          report.push_back({{"trees", n}, {"cold_ms", msSince(t)}});
        }
        fsdb::CsgSearchResult a, b;
        const auto pruned = timeRuns(reps, [&] { a = fsdb::searchCsg(*store, q, options, cache); });
        options.prune = false;
        const auto full = timeRuns(fullReps, [&] { b = fsdb::searchCsg(*store, q, options, cache); });
        const fsdb::bench::Comparison c = compareRuns(pruned, full, a, b);
        std::printf("%-75s %5zu %7zu %7zu %8.1f %8.1f %9.1f %6.1fx %6s\n", ("'" + text + "'").c_str(), a.hits.size(),
                    a.bounded, a.matched, c.p50, c.p95, c.refP50, c.ratio(), c.equal ? "yes" : "NO");
        std::fflush(stdout);
        report.push_back({{"trees", n}, {"query", text}, {"bounded", a.bounded}, {"matched", a.matched},
                          {"p50_ms", c.p50}, {"p95_ms", c.p95}, {"full_p50_ms", c.refP50}, {"ratio", c.ratio()},
                          {"equal", c.equal}, {"reps", reps}, {"full_reps", fullReps}});
        if (!c.equal) {
          std::cerr << "pruned and unpruned answers differ for '" << text << "'\n";
          return 1;
        }
      }
    }
    return 0;
  });
}
