// The two store backends side by side (db/store.h): bulk import, linguistic search and structural
// search on one catalogue of N parts and M trees, built the same way into an SQLite file and into
// a PostgreSQL schema, in one run. Reports medians and the PostgreSQL / SQLite ratio of each.
//
// Usage: bench_backends --postgres URL [--parts 100000] [--trees 10000] [--dir DIR] [--reps R]
//                       [--benchmark_out=FILE.json]
// bench/bench_backends.sh starts a throwaway cluster (scripts/pg-test-cluster) and runs this.
// Both databases are built anew on every run: DIR/backends.sqlite and the schema bench_backends
// (dropped first). Parts are random superquadrics (seeded; a fifth bent, a tenth tapered, a tenth
// twisted, a third of the values fuzzy) imported through prepareDocument and Store::createBatch in
// batches of 2000, as POST /parts/bulk does; trees are unions and differences of 2 to 4 stored
// parts by name, some placed. Every query runs R times on each backend; answers must be equal.
// The PostgreSQL schema is vacuumed and analyzed after the import, before the queries.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_stats.h"
#include "db/postgres.h"
#include "db/store.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/csg_search.h"
#include "server/service/descriptor_rows.h"
#include "server/service/documents.h"
#include "server/service/linguistic_search.h"

namespace {

using fsdb::bench::Clock;
using fsdb::bench::msSince;
using fsdb::bench::percentile;
using fsdb::bench::timeRuns;
using nlohmann::json;

json value(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(0, 1);
  const double m = lo + (hi - lo) * u(rng);
  if (u(rng) >= 0.3) return m;
  const double s = (hi - lo) * (0.02 + 0.08 * u(rng));
  return {{"tri", {std::max(lo, m - s), m, std::min(hi, m + s)}}};
}

json partDocument(std::mt19937& rng, size_t i) {
  std::uniform_real_distribution<double> u(0, 1);
  json params = {{"eps1", value(rng, 0.1, 2.5)},
                 {"eps2", value(rng, 0.1, 2.5)},
                 {"a1", value(rng, 0.3, 3.0)},
                 {"a2", value(rng, 0.3, 2.0)},
                 {"a3", value(rng, 0.5, 3.0)}};
  if (u(rng) < 0.2) params["kv"] = value(rng, 0.0, 0.15);
  if (u(rng) < 0.1) params["kx"] = value(rng, 0.0, 0.9);
  if (u(rng) < 0.1) params["t"] = value(rng, 0.0, 3.0);
  return {{"kind", "part"}, {"name", "p-" + std::to_string(i)}, {"params", params}};
}

json treeDocument(std::mt19937& rng, size_t i, size_t parts) {
  std::uniform_int_distribution<size_t> part(1, parts);
  json children = json::array();
  const int n = 2 + static_cast<int>(rng() % 3);
  for (int k = 0; k < n; ++k) {
    json leaf = {{"part", "p-" + std::to_string(part(rng))}};
    if (k > 0) leaf["transform"] = {{"translate", {static_cast<int>(rng() % 5), static_cast<int>(rng() % 5), 0}}};
    children.push_back(leaf);
  }
  return {{"kind", "shape"},
          {"name", "tree-" + std::to_string(i)},
          {"tree", {{"op", rng() % 4 == 0 ? "difference" : "union"}, {"children", children}}}};
}

// Imports `count` documents made by `make` in batches; documents per second.
template <class Make>
double importAll(fsdb::Store& store, const std::string& kind, size_t count, Make make) {
  std::mt19937 rng(kind == "part" ? 42 : 43);
  const auto start = Clock::now();
  for (size_t done = 0; done < count;) {
    std::vector<fsdb::NewObject> items;
    for (size_t k = 0; k < 2000 && done < count; ++k, ++done)
      items.push_back(fsdb::prepareDocument(make(rng, done + 1), kind, store, fsdb::DocumentLimits{}, ""));
    for (const fsdb::BulkItemResult& r : store.createBatch(items, fsdb::BulkMode::kCreate))
      if (!r.errorCode.empty()) throw fsdb::Error(r.errorCode, r.errorMessage, r.errorPath);
  }
  return count / (msSince(start) / 1000);
}

const std::vector<std::string> kLinguistic = {"find a very twisted part", "find a slightly bent part",
                                              "find a very tapered and slightly bent part", "find a very round part",
                                              "find a big part"};
const std::vector<std::string> kCsg = {"the union of a very bent cylinder and a sphere", "a box minus a cylinder",
                                       "\"p-7\" + \"p-11\"",
                                       "the union of a very round part and a twisted box and a cylinder"};

struct Backend {
  std::string name, location;
  std::unique_ptr<fsdb::Store> store;
  double partsPerSecond = 0, treesPerSecond = 0, refreshMs = 0, coldCsgMs = 0;
};

}  // namespace

int main(int argc, char** argv) {
  size_t parts = 100000, trees = 10000;
  int reps = 11;
  std::string postgres, dir = "build/bench-data", out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--parts") parts = std::stoul(next());
    else if (a == "--trees") trees = std::stoul(next());
    else if (a == "--reps") reps = std::stoi(next());
    else if (a == "--postgres") postgres = next();
    else if (a == "--dir") dir = next();
    else if (a.rfind("--benchmark_out=", 0) == 0) out = a.substr(16);
    else if (a.rfind("--benchmark_", 0) == 0) continue;
    else {
      std::cerr << "unknown argument " << a << "\n";
      return 2;
    }
  }
  if (postgres.empty()) {
    std::cerr << "bench_backends: --postgres URL is required (bench/bench_backends.sh starts a cluster)\n";
    return 2;
  }
  std::filesystem::create_directories(dir);
  return fsdb::bench::runReport("bench_backends", out, [&](json& report) {
    std::vector<Backend> backends(2);
    backends[0].name = "sqlite";
    backends[0].location = dir + "/backends.sqlite";
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(backends[0].location + suffix);
    backends[1].name = "postgresql";
    backends[1].location = postgres + (postgres.find('?') == std::string::npos ? "?" : "&") + "schema=bench_backends";
    fsdb::postgres::Connection(fsdb::postgres::parseAddress(postgres))
        .exec("DROP SCHEMA IF EXISTS bench_backends CASCADE");

    for (Backend& b : backends) {
      b.store = fsdb::Store::open(b.location);
      b.partsPerSecond = importAll(*b.store, "part", parts, partDocument);
      b.treesPerSecond =
          importAll(*b.store, "shape", trees, [&](std::mt19937& rng, size_t i) { return treeDocument(rng, i, parts); });
      const auto t = Clock::now();
      fsdb::refreshPendingDescriptors(*b.store, 10000);  // trees with references are written pending
      b.refreshMs = msSince(t);
      std::fprintf(stderr, "%s: %zu parts at %.0f/s, %zu trees at %.0f/s, pending rows in %.0f ms\n", b.name.c_str(),
                   parts, b.partsPerSecond, trees, b.treesPerSecond, b.refreshMs);
    }
    // The queries are timed in the steady state: PostgreSQL's autovacuum would otherwise analyze
    // the new tables while they run (taking one of the two cores from both backends' timings).
    fsdb::postgres::Connection(fsdb::postgres::parseAddress(backends[1].location)).exec("VACUUM ANALYZE");
    std::printf("== %zu parts, %zu trees; medians of %d runs; ratio = postgresql / sqlite\n", parts, trees, reps);
    std::printf("%-58s %12s %12s %7s\n", "", "sqlite", "postgresql", "ratio");
    const auto row = [&](const std::string& what, double s, double p, const char* unit) {
      std::printf("%-58s %10.1f %s %10.1f %s %7.2f\n", what.c_str(), s, unit, p, unit, p / s);
      report.push_back({{"what", what}, {"sqlite", s}, {"postgresql", p}, {"unit", unit}, {"ratio", p / s}});
    };
    row("bulk import, parts (docs/s)", backends[0].partsPerSecond, backends[1].partsPerSecond, "/s");
    row("bulk import, trees (docs/s)", backends[0].treesPerSecond, backends[1].treesPerSecond, "/s");
    row("descriptor rows of the pending trees", backends[0].refreshMs, backends[1].refreshMs, "ms");

    for (const std::string& text : kLinguistic) {
      const fsdb::LinguisticQuery q = fsdb::parseLinguisticQuery(text, fsdb::Vocabulary::builtin());
      fsdb::LinguisticSearchOptions options;
      options.limit = 10;
      double p50[2];
      std::vector<int64_t> hits[2];
      for (int k = 0; k < 2; ++k) {
        fsdb::LinguisticSearchResult r;
        p50[k] = percentile(timeRuns(reps, [&] { r = fsdb::searchLinguistic(*backends[k].store, q, options); }), 0.5);
        for (const fsdb::LinguisticHit& h : r.hits) hits[k].push_back(h.id);
      }
      if (hits[0] != hits[1]) throw fsdb::Error("bench", "'" + text + "': the backends answer differently");
      row("linguistic: " + text, p50[0], p50[1], "ms");
    }
    fsdb::StoredGraphCache caches[2];
    for (const std::string& text : kCsg) {
      double p50[2];
      std::vector<int64_t> hits[2];
      for (int k = 0; k < 2; ++k) {
        const fsdb::CsgQuery q =
            fsdb::parseCsgQuery(text, fsdb::Vocabulary::builtin(), fsdb::storeResolver(*backends[k].store), 10000);
        fsdb::CsgSearchOptions options;
        options.limit = 10;
        if (caches[k].size() == 0) {
          const auto t = Clock::now();
          fsdb::searchCsg(*backends[k].store, q, options, caches[k]);
          backends[k].coldCsgMs = msSince(t);
        }
        fsdb::CsgSearchResult r;
        p50[k] =
            percentile(timeRuns(reps, [&] { r = fsdb::searchCsg(*backends[k].store, q, options, caches[k]); }), 0.5);
        for (const auto& h : r.hits) hits[k].push_back(h.id);
      }
      if (hits[0] != hits[1]) throw fsdb::Error("bench", "'" + text + "': the backends answer differently");
      row("csg: " + text, p50[0], p50[1], "ms");
    }
    row("csg: first query (every tree's graph built)", backends[0].coldCsgMs, backends[1].coldCsgMs, "ms");
    double seq[2];
    for (int k = 0; k < 2; ++k) seq[k] = percentile(timeRuns(200, [&] { backends[k].store->changeSeq(); }), 0.5);
    row("change check per search (Store::changeSeq)", seq[0], seq[1], "ms");
    return 0;
  });
}
