// Speed of fuzzy Bézier evaluation (geometry/curves/fuzzy_bezier.h): one point of the three curves at
// one level for polynomial and rational curves of n control points (the cost an HTTP request
// pays per u value; --max-control-points bounds n), and one point of a 16 x 16 surface.
#include <benchmark/benchmark.h>

#include <random>

#include "geometry/curves/fuzzy_bezier.h"

namespace {

using fsdb::FuzzyNumber;

FuzzyNumber randomTri(std::mt19937& rng) {
  std::uniform_real_distribution<double> m(-5, 5), side(0.1, 1);
  const double x = m(rng);
  return FuzzyNumber::triangular(x - side(rng), x, x + side(rng));
}

fsdb::FuzzyBezierCurve curve(std::size_t n, bool rational) {
  std::mt19937 rng(1);
  fsdb::FuzzyBezierCurve c;
  for (std::size_t k = 0; k < n; ++k) {
    c.controlPoints.push_back({randomTri(rng), randomTri(rng), randomTri(rng)});
    if (rational) c.weights.push_back(FuzzyNumber::triangular(0.5, 1, 2));
  }
  return c;
}

void evaluateAlongTheCurve(benchmark::State& state, bool rational) {
  const fsdb::BezierCurveCut cut = fsdb::cutCurve(curve(static_cast<std::size_t>(state.range(0)), rational), 0.5);
  int step = 0;
  for (auto _ : state) benchmark::DoNotOptimize(fsdb::evaluateCut(cut, (step++ % 101) / 100.0));
}

void BM_CurvePoint(benchmark::State& state) { evaluateAlongTheCurve(state, false); }
BENCHMARK(BM_CurvePoint)->Arg(4)->Arg(16)->Arg(256);

void BM_RationalCurvePoint(benchmark::State& state) { evaluateAlongTheCurve(state, true); }
BENCHMARK(BM_RationalCurvePoint)->Arg(4)->Arg(16)->Arg(256);

void BM_SurfacePoint16x16(benchmark::State& state) {
  std::mt19937 rng(2);
  fsdb::FuzzyBezierSurface s;
  for (int i = 0; i < 16; ++i) {
    s.controlGrid.emplace_back();
    for (int j = 0; j < 16; ++j) s.controlGrid.back().push_back({randomTri(rng), randomTri(rng), randomTri(rng)});
  }
  const fsdb::BezierSurfaceCut cut = fsdb::cutSurface(s, 0.5);
  int step = 0;
  for (auto _ : state) {
    const double t = (step++ % 101) / 100.0;
    benchmark::DoNotOptimize(fsdb::evaluateCut(cut, t, 1 - t));
  }
}
BENCHMARK(BM_SurfacePoint16x16);

}  // namespace
