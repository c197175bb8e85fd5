// Speed of the voxel envelopes (geometry/voxel/envelope_grid.h): building the upper/lower
// grids of a ball whose support r3 = 1 spans a grid of N = 64, 128, 256 voxels (h = 2/N),
// fuzzy (tri(0.6, 0.8, 1.0): the shell 0.6..1 is a volume of voxels) and crisp (radius 1: only
// the surface blocks hold voxels); the volumes at 11 levels; the union of two such balls; and,
// for scale, OpenVDB's own tools::createLevelSetSphere (narrow band of half-width 3) at the
// same voxel size.
// Counters: active voxels (one by one, tiles apart), tiles, memory of both grids, and the time
// per active voxel (compare the last with createLevelSetSphere's).
#include <benchmark/benchmark.h>

#include <vector>

#include "bench/grid_bench.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

const Vec3 kCentre{0.013, -0.021, 0.007};  // off the lattice

void buildBall(benchmark::State& state, double r1, double r2) {
  const double h = 2.0 / static_cast<double>(state.range(0));
  bench::timeGridBuild(state, FuzzyBall(kCentre, r1, r2, 1.0), h);
}

void BM_FuzzyBallBuild(benchmark::State& state) { buildBall(state, 0.6, 0.8); }
void BM_CrispBallBuild(benchmark::State& state) { buildBall(state, 1.0, 1.0); }

void BM_FuzzyBallVolumes(benchmark::State& state) {
  const EnvelopeGrid g =
      EnvelopeGrid::build(FuzzyBall(kCentre, 0.6, 0.8, 1.0), 2.0 / state.range(0));
  std::vector<double> alphas;
  for (int i = 0; i <= 10; ++i) alphas.push_back(i / 10.0);
  for (auto _ : state) benchmark::DoNotOptimize(g.volumes(alphas));
  bench::setGridCounters(state, g.stats());
}

// The Boolean of two overlapping fuzzy balls of radius up to 1 (support 2 = N voxels across).
void BM_FuzzyBallUnion(benchmark::State& state) {
  const double h = 2.0 / static_cast<double>(state.range(0));
  const EnvelopeGrid a = EnvelopeGrid::build(FuzzyBall(kCentre, 0.6, 0.8, 1.0), h);
  const EnvelopeGrid b = EnvelopeGrid::build(FuzzyBall(kCentre + Vec3{0.9, 0, 0}, 0.5, 0.7, 0.9), h);
  EnvelopeGridStats stats;
  for (auto _ : state) {
    const EnvelopeGrid u = combine(a, b, BooleanOp::kUnion);
    stats = u.stats();
    benchmark::DoNotOptimize(stats);
  }
  bench::setGridCounters(state, stats);
}

void BM_OpenVdbLevelSetSphere(benchmark::State& state) {
  bench::timeLevelSetSphere(state, 1.0f, kCentre, 2.0f / static_cast<float>(state.range(0)));
}

BENCHMARK(BM_FuzzyBallBuild)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CrispBallBuild)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FuzzyBallVolumes)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FuzzyBallUnion)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenVdbLevelSetSphere)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace fsdb
