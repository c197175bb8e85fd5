#pragma once
// What the search benches (bench_linguistic, bench_csg_search) share: percentiles of timings and
// the pruned-equals-full check of two result lists (ids and scores, in order).
#include <algorithm>
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

}  // namespace fsdb::bench
