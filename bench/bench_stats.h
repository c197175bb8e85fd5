#pragma once
// What the search benches (bench_linguistic, bench_csg_search) share: their command line, timing
// repeated runs, percentiles of timings, the pruned-equals-full check of two result lists (ids and
// scores, in order), the summary row of a fast path measured against its reference path and the
// run that writes the JSON report.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/core/error.h"

namespace fsdb::bench {

inline double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
}

// Result: anything with hits[i].id and hits[i].score.score.
template <class Result>
bool sameHits(const Result& a, const Result& b) {
  if (a.hits.size() != b.hits.size()) return false;
  for (size_t i = 0; i < a.hits.size(); ++i)
    if (a.hits[i].id != b.hits[i].id || a.hits[i].score.score != b.hits[i].score.score) return false;
  return true;
}

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// Runs f() reps times; the milliseconds of each run, in order.
template <class F>
std::vector<double> timeRuns(int reps, F&& f) {
  std::vector<double> ms;
  for (int r = 0; r < reps; ++r) {
    const auto t = Clock::now();
    f();
    ms.push_back(msSince(t));
  }
  return ms;
}

// A fast path (pruned, indexed) against its reference path (full, scan). With no reference runs
// (reps 0, for profiling) refP50 is 0 and the answers count as equal.
struct Comparison {
  double p50 = 0, p95 = 0, refP50 = 0;
  bool equal = true;
  double ratio() const { return refP50 / p50; }
};

template <class Result>
Comparison compareRuns(const std::vector<double>& fast, const std::vector<double>& ref, const Result& a,
                       const Result& b) {
  Comparison c;
  c.p50 = percentile(fast, 0.5);
  c.p95 = percentile(fast, 0.95);
  c.refP50 = ref.empty() ? 0.0 : percentile(ref, 0.5);
  c.equal = ref.empty() || sameHits(a, b);
  return c;
}

// The command line: [--sizes N,M] [--dir DIR] [--reps R] [<refFlag> S] [--benchmark_out=FILE.json];
// other --benchmark_* flags are ignored, so scripts/run-benchmarks can run the bench.
struct Args {
  std::vector<size_t> sizes;  // empty: the bench's default
  std::string dir = "build/bench-data", out;
  std::string only;   // --only TEXT: just the cases whose name contains TEXT (profiling one)
  int reps, refReps;  // fast path, reference path
};

// Fills args (its reps and refReps hold the defaults); false, after a message, on an unknown argument.
inline bool parseArgs(int argc, char** argv, const std::string& refFlag, Args& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--sizes") {
      std::stringstream ss(next());
      for (std::string s; std::getline(ss, s, ',');) args.sizes.push_back(std::stoul(s));
    } else if (a == "--dir") args.dir = next();
    else if (a == "--reps") args.reps = std::stoi(next());
    else if (a == "--only") args.only = next();
    else if (a == refFlag) args.refReps = std::stoi(next());
    else if (a.rfind("--benchmark_out=", 0) == 0) args.out = a.substr(16);
    else if (a.rfind("--benchmark_", 0) == 0) continue;
    else {
      std::cerr << "unknown argument " << a << "\n";
      return false;
    }
  }
  return true;
}

// Runs body(report) (its exit status; rows go into the JSON array report), reports an fsdb::Error
// as "name: code: message (path)" with status 1, and writes the report to out when one is named.
template <class F>
int runReport(const char* name, const std::string& out, F&& body) {
  nlohmann::json report = nlohmann::json::array();
  try {
    if (const int rc = body(report)) return rc;
  } catch (const fsdb::Error& e) {
    std::cerr << name << ": " << e.code() << ": " << e.what() << " (" << e.path() << ")\n";
    return 1;
  }
  if (!out.empty()) std::ofstream(out) << report.dump(2) << "\n";
  return 0;
}

}  // namespace fsdb::bench
