// Speed of evaluating crisp superquadric parts at world points: the inner loop of voxel
// evaluation (docs/api.md §3). Reports ns per call for a plain sphere and for a bent, tapered,
// twisted, placed part, for both the inside-outside value and the pseudo distance. The
// Prepared variants are what a voxel loop uses; the Placed ones rebuild the rotation per call.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric.h"

namespace fsdb {
namespace {

// A fixed cloud of points around the part, so branch patterns are realistic (about half inside).
std::vector<Vec3> samplePoints(double range) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-range, range);
  std::vector<Vec3> points(4096);
  for (auto& p : points) p = {u(rng), u(rng), u(rng)};
  return points;
}

PlacedSuperquadric sphere() {
  PlacedSuperquadric part;  // unit sphere, identity placement
  return part;
}

PlacedSuperquadric deformedPart() {
  PlacedSuperquadric part;
  part.params.eps1 = 0.7;
  part.params.eps2 = 1.3;
  part.params.a1 = 1.0;
  part.params.a2 = 0.8;
  part.params.a3 = 2.0;
  part.params.kx = 0.4;
  part.params.ky = -0.3;
  part.params.t = 1.2;
  part.params.kv = 0.3;
  part.placement.translate = {0.5, -0.25, 0.1};
  part.placement.axis = {1, 1, 0};
  part.placement.deg = 30;
  part.placement.scale = 1.5;
  return part;
}

template <typename Part, typename Eval>
void run(benchmark::State& state, const Part& part, double range, Eval eval) {
  const auto points = samplePoints(range);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(eval(part, points[i]));
    i = (i + 1) & (points.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_CanonicalSphere_InsideOutside(benchmark::State& state) {
  const auto points = samplePoints(1.3);
  const SuperquadricParams params;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(insideOutside(params, points[i]));
    i = (i + 1) & (points.size() - 1);
  }
}
BENCHMARK(BM_CanonicalSphere_InsideOutside);

void BM_Sphere_InsideOutside_Prepared(benchmark::State& state) {
  run(state, PreparedSuperquadric(sphere()), 1.3,
      [](const PreparedSuperquadric& p, const Vec3& w) { return p.insideOutside(w); });
}
BENCHMARK(BM_Sphere_InsideOutside_Prepared);

void BM_Sphere_PseudoDistance_Prepared(benchmark::State& state) {
  run(state, PreparedSuperquadric(sphere()), 1.3,
      [](const PreparedSuperquadric& p, const Vec3& w) { return p.pseudoDistance(w); });
}
BENCHMARK(BM_Sphere_PseudoDistance_Prepared);

void BM_BentTaperedTwisted_InsideOutside_Prepared(benchmark::State& state) {
  run(state, PreparedSuperquadric(deformedPart()), 3.5,
      [](const PreparedSuperquadric& p, const Vec3& w) { return p.insideOutside(w); });
}
BENCHMARK(BM_BentTaperedTwisted_InsideOutside_Prepared);

void BM_BentTaperedTwisted_PseudoDistance_Prepared(benchmark::State& state) {
  run(state, PreparedSuperquadric(deformedPart()), 3.5,
      [](const PreparedSuperquadric& p, const Vec3& w) { return p.pseudoDistance(w); });
}
BENCHMARK(BM_BentTaperedTwisted_PseudoDistance_Prepared);

void BM_Sphere_InsideOutside_Placed(benchmark::State& state) {
  run(state, sphere(), 1.3,
      [](const PlacedSuperquadric& p, const Vec3& w) { return p.insideOutside(w); });
}
BENCHMARK(BM_Sphere_InsideOutside_Placed);

void BM_BentTaperedTwisted_InsideOutside_Placed(benchmark::State& state) {
  run(state, deformedPart(), 3.5,
      [](const PlacedSuperquadric& p, const Vec3& w) { return p.insideOutside(w); });
}
BENCHMARK(BM_BentTaperedTwisted_InsideOutside_Placed);

}  // namespace
}  // namespace fsdb
