// Speed of the interval enclosure of a placed superquadric's inside-outside function over a
// voxel block and a parameter box (superquadric_bounds.h): the per-block test of sparse
// voxel evaluation of fuzzy parts. Reports ns per enclosure for a crisp unit sphere and for a
// fuzzy (every parameter and the placement spread by about 5%) bent, tapered, twisted, placed
// part, over blocks of edge 0.1 scattered around the part, and the crisp point evaluation of
// the same part for scale.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb {
namespace {

struct Block {
  Interval x, y, z;
};

// A fixed set of blocks of edge `edge` with corners in [−range, range]³.
std::vector<Block> sampleBlocks(double range, double edge) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-range, range - edge);
  std::vector<Block> blocks(4096);
  for (auto& b : blocks) {
    const double x = u(rng), y = u(rng), z = u(rng);
    b = {{x, x + edge}, {y, y + edge}, {z, z + edge}};
  }
  return blocks;
}

PlacedSuperquadric deformedPart() {
  PlacedSuperquadric part;
  part.params = {0.7, 1.3, 1.0, 0.8, 2.0, 0.4, -0.3, 0.3, 1.2};
  part.placement.translate = {0.5, -0.25, 0.1};
  part.placement.axis = {1, 1, 0};
  part.placement.deg = 30;
  part.placement.scale = 1.5;
  return part;
}

// The deformed part with every value spread by ±5% (angles by ±3°, taper and twist by ±0.05).
PartBox fuzzyDeformedPart() {
  PartBox box = crispPartBox(deformedPart());
  const auto spread = [](Interval& a, double s) { a = {a.lo - s, a.hi + s}; };
  SuperquadricBox& q = box.params;
  spread(q.eps1, 0.035);
  spread(q.eps2, 0.065);
  spread(q.a1, 0.05);
  spread(q.a2, 0.04);
  spread(q.a3, 0.1);
  spread(q.kx, 0.05);
  spread(q.ky, 0.05);
  spread(q.kv, 0.015);
  spread(q.t, 0.05);
  PlacementBox& p = box.placement;
  spread(p.tx, 0.05);
  spread(p.ty, 0.05);
  spread(p.tz, 0.05);
  spread(p.deg, 3.0);
  spread(p.scale, 0.075);
  return box;
}

void runBounds(benchmark::State& state, const PartBox& part, double range) {
  const auto blocks = sampleBlocks(range, 0.1);
  size_t i = 0;
  for (auto _ : state) {
    const Block& b = blocks[i];
    benchmark::DoNotOptimize(insideOutsideBounds(part, b.x, b.y, b.z));
    i = (i + 1) & (blocks.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Bounds_CrispSphere(benchmark::State& state) {
  runBounds(state, crispPartBox(PlacedSuperquadric()), 1.3);
}
BENCHMARK(BM_Bounds_CrispSphere);

void BM_Bounds_CrispBentTaperedTwisted(benchmark::State& state) {
  runBounds(state, crispPartBox(deformedPart()), 3.5);
}
BENCHMARK(BM_Bounds_CrispBentTaperedTwisted);

void BM_Bounds_FuzzyBentTaperedTwisted(benchmark::State& state) {
  runBounds(state, fuzzyDeformedPart(), 3.5);
}
BENCHMARK(BM_Bounds_FuzzyBentTaperedTwisted);

void BM_Homogeneous_FuzzyBentTaperedTwisted(benchmark::State& state) {
  const PartBox part = fuzzyDeformedPart();
  const auto blocks = sampleBlocks(3.5, 0.1);
  size_t i = 0;
  for (auto _ : state) {
    const Block& b = blocks[i];
    benchmark::DoNotOptimize(homogeneousInsideOutsideBounds(part, b.x, b.y, b.z));
    i = (i + 1) & (blocks.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Homogeneous_FuzzyBentTaperedTwisted);

// For scale: one crisp point evaluation of the same part (bench_superquadric.cpp measures more).
void BM_Point_BentTaperedTwisted_Prepared(benchmark::State& state) {
  const PreparedSuperquadric part(deformedPart());
  const auto blocks = sampleBlocks(3.5, 0.1);
  size_t i = 0;
  for (auto _ : state) {
    const Block& b = blocks[i];
    benchmark::DoNotOptimize(part.insideOutside({b.x.lo, b.y.lo, b.z.lo}));
    i = (i + 1) & (blocks.size() - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Point_BentTaperedTwisted_Prepared);

// How often an enclosure decides a block (hi <= 1 or lo > 1) rather than asking for refinement;
// reported as counters, once, so the speed numbers above can be read against usefulness.
void BM_DecidedFraction_FuzzyBentTaperedTwisted(benchmark::State& state) {
  const PartBox part = fuzzyDeformedPart();
  const auto blocks = sampleBlocks(3.5, 0.1);
  double decided = 0;
  for (auto _ : state) {
    decided = 0;
    for (const Block& b : blocks) {
      const Interval r = insideOutsideBounds(part, b.x, b.y, b.z);
      decided += (r.hi <= 1.0 || r.lo > 1.0) ? 1 : 0;
    }
  }
  state.counters["decided"] = decided / blocks.size();
}
BENCHMARK(BM_DecidedFraction_FuzzyBentTaperedTwisted)->Iterations(1);

}  // namespace
}  // namespace fsdb
