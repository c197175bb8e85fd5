#pragma once
// What the search benches (bench_linguistic, bench_csg_search) share: timing repeated runs,
// percentiles of timings, the pruned-equals-full check of two result lists (ids and scores, in
// order) and the summary row of a fast path measured against its reference path.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

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

}  // namespace fsdb::bench
