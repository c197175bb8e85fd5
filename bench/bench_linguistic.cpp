// Linguistic search speed: POST /query/linguistic's search (server/service/linguistic_search.h)
// on catalogues of N random parts, the descriptor index's candidates against the full scan, in
// one run. Goals: p50 < 50 ms at 1M parts, indexed >= 10x faster than the scan.
//
// Usage: bench_linguistic [--sizes 100000,1000000] [--dir DIR] [--reps R] [--scan-reps S]
//                         [--only TEXT] [--benchmark_out=FILE.json] (other --benchmark_* flags are ignored, so
//                         scripts/run-benchmarks can run it; it then measures 100000 parts)
// A catalogue is built once per size into DIR/parts-N.sqlite (default build/bench-data) and
// reused by later runs: random parts (seeded) go through the same code as POST /parts/bulk
// (importDocuments: prepareDocument's validation, describePart and descriptor rows on all cores,
// Store::createBatch in transactions of 10000), so the database is what an import makes.
// Every query runs R times indexed and S times as a scan; both answers must be equal.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_stats.h"
#include "db/store.h"
#include "query/document/part_json.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/bulk_import.h"
#include "server/service/documents.h"
#include "server/service/linguistic_search.h"

namespace {

using fsdb::bench::Clock;
using fsdb::bench::compareRuns;
using fsdb::bench::msSince;
using fsdb::bench::timeRuns;

// Mostly crisp deformations (a catalogue of plain parts with some bent, tapered, twisted ones),
// about a third of the values fuzzy.
fsdb::FuzzyNumber value(std::mt19937& rng, double lo, double hi, double fuzzyShare) {
  std::uniform_real_distribution<double> u(0, 1);
  const double m = lo + (hi - lo) * u(rng);
  if (u(rng) >= fuzzyShare) return fsdb::FuzzyNumber::crisp(m);
  const double s = (hi - lo) * (0.02 + 0.08 * u(rng));
  return fsdb::FuzzyNumber::triangular(std::max(lo, m - s), m, std::min(hi, m + s));
}

fsdb::FuzzyPart randomPart(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  fsdb::FuzzyPart p;
  p.eps1 = value(rng, 0.1, 2.5, 0.3);
  p.eps2 = value(rng, 0.1, 2.5, 0.3);
  p.a1 = value(rng, 0.3, 3.0, 0.3);
  p.a2 = value(rng, 0.3, 2.0, 0.2);
  p.a3 = value(rng, 0.3, 3.0, 0.2);
  // a fifth of the parts bent, a tenth tapered, a tenth twisted
  if (u(rng) < 0.2) p.kv = value(rng, 0.0, 0.4 / (p.a1.support().hi * p.a3.support().hi), 0.5);
  if (u(rng) < 0.1) p.kx = value(rng, 0.0, 0.9, 0.5);
  if (u(rng) < 0.1) p.t = value(rng, 0.0, 3.0, 0.5);
  p.tx = value(rng, -10, 10, 0.2);
  p.ty = value(rng, -10, 10, 0.2);
  return p;
}

void build(const std::string& path, size_t n) {
  const std::string tmp = path + ".building";
  std::filesystem::remove(tmp);
  auto store = fsdb::Store::open(tmp);
  std::mt19937 rng(42);
  const auto start = Clock::now();
  std::vector<fsdb::BulkLine> lines;
  lines.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    nlohmann::json doc = fsdb::partToJson(randomPart(rng));
    doc["kind"] = "part";
    char name[32];
    std::snprintf(name, sizeof name, "part-%07zu", i + 1);
    doc["name"] = name;
    lines.push_back({i + 1, std::move(doc), nullptr});
  }
  fsdb::BulkOptions options;
  options.batchSize = 10000;
  options.progress = [&](size_t done, size_t) {
    if (done % 100000 == 0 || done == n) std::fprintf(stderr, "  %zu parts, %.0f s\n", done, msSince(start) / 1000);
  };
  const fsdb::BulkReport report = fsdb::importDocuments(*store, lines, options);
  if (report.failed > 0) throw fsdb::Error(fsdb::errc::kStorage, "catalogue: " + report.errors[0].dump());
  store->checkpoint();
  store.reset();
  std::filesystem::rename(tmp, path);
  std::fprintf(stderr, "built %s: %zu parts in %.1f s\n", path.c_str(), n, msSince(start) / 1000);
}

const std::vector<std::string> kQueries = {
    "find a very twisted part",                    // selective: a tenth twisted, few very
    "find a slightly bent part",                   // a fifth bent
    "find a very tapered and slightly bent part",  // and of two selective conditions
    "find a very round part",                      // broad: exponents near 1
    "find a big part",                             // broad: most parts have some size
};

}  // namespace

int main(int argc, char** argv) {
  fsdb::bench::Args args;
  args.reps = 21, args.refReps = 3;
  if (!fsdb::bench::parseArgs(argc, argv, "--scan-reps", args)) return 2;
  if (args.sizes.empty()) args.sizes = {100000};
  const std::string& dir = args.dir;
  const int reps = args.reps, scanReps = args.refReps;
  std::filesystem::create_directories(dir);
  return fsdb::bench::runReport("bench_linguistic", args.out, [&](nlohmann::json& report) {
    for (size_t n : args.sizes) {
      const std::string path = dir + "/parts-" + std::to_string(n) + ".sqlite";
      if (!std::filesystem::exists(path)) build(path, n);
      auto store = fsdb::Store::open(path);
      std::printf("== %zu parts (%s, %.0f MB)\n", n, path.c_str(), std::filesystem::file_size(path) / 1e6);
      std::printf("%-45s %9s %9s %9s %10s %7s %9s %6s\n", "query", "hits", "cands", "p50 ms", "p95 ms", "scan ms",
                  "ratio", "equal");
      for (const std::string& text : kQueries) {
        if (text.find(args.only) == std::string::npos) continue;  // --only
        const fsdb::LinguisticQuery q = fsdb::parseLinguisticQuery(text, fsdb::Vocabulary::builtin());
        fsdb::LinguisticSearchOptions options;
        options.kinds = fsdb::searchKinds(q, "");
        options.limit = 10;
        fsdb::LinguisticSearchResult a, b;
        const auto indexed = timeRuns(reps, [&] { a = fsdb::searchLinguistic(*store, q, options); });
        options.scan = true;
        const auto scanned = timeRuns(scanReps, [&] { b = fsdb::searchLinguistic(*store, q, options); });
        // --scan-reps 0: index only (profiling)
        const fsdb::bench::Comparison c = compareRuns(indexed, scanned, a, b);
        std::printf("%-45s %9zu %9zu %9.2f %10.2f %7.0f %8.1fx %6s\n", ("\"" + text + "\"").c_str(), a.hits.size(),
                    a.candidates, c.p50, c.p95, c.refP50, c.ratio(), c.equal ? "yes" : "NO");
        std::fflush(stdout);
        report.push_back({{"parts", n},
                          {"query", text},
                          {"candidates", a.candidates},
                          {"scanned", b.candidates},
                          {"p50_ms", c.p50},
                          {"p95_ms", c.p95},
                          {"scan_p50_ms", c.refP50},
                          {"ratio", c.ratio()},
                          {"equal", c.equal},
                          {"reps", reps},
                          {"scan_reps", scanReps}});
        if (!c.equal) {
          std::cerr << "indexed and scan answers differ for \"" << text << "\"\n";
          return 1;
        }
      }
    }
    return 0;
  });
}
