// Candidate generation of fair curves (Bernardes, Wu & D'Ottaviano;
// geometry/curves/fair_candidates.h) for 4, 16, 64 points on a closed, slightly irregular loop:
// first estimation, each point's fuzzy set sampled at 180 angles and defuzzified by local maxima,
// every candidate scored (AND over the points). The "WithCurves" variant also builds and samples
// the returned curves (32 points a piece), as POST /curves/fair does.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/curves/fair_candidates.h"
#include "geometry/curves/fair_curve.h"

namespace {

std::vector<fsdb::Vec2> loop(int n) {
  std::vector<fsdb::Vec2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, r = 3 + 0.6 * std::cos(2 * a) + 0.05 * std::sin(7.0 * i);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

void BM_FairCandidates(benchmark::State& state) {
  const auto p = loop(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(fsdb::fairCandidates(p, true));
}
BENCHMARK(BM_FairCandidates)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

void BM_FairCandidatesWithCurves(benchmark::State& state) {
  const auto p = loop(static_cast<int>(state.range(0)));
  const auto r = fsdb::radiusMagnitudes(p, {}, true);
  for (auto _ : state) {
    for (const auto& c : fsdb::fairCandidates(p, true))
      benchmark::DoNotOptimize(fsdb::sampleFairCurve(fsdb::buildFairCurve(p, c.anglesDeg, r, true), 32));
  }
}
BENCHMARK(BM_FairCandidatesWithCurves)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

}  // namespace
