#pragma once
// Shared pieces of the voxel-grid benchmarks: timing EnvelopeGrid::build with its counters
// (active voxels, tiles, memory, time per active voxel), the voxel size that puts N voxels across
// a source's bounding box, and OpenVDB's createLevelSetSphere as the yardstick.
#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <algorithm>

#include "geometry/voxel/envelope_grid.h"
#include "geometry/voxel/envelope_grid_vdb.h"

namespace fsdb::bench {

inline benchmark::Counter perActiveVoxel(double activeVoxels) {
  return benchmark::Counter(activeVoxels, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

inline void setGridCounters(benchmark::State& state, const EnvelopeGridStats& s) {
  state.counters["active_voxels"] = static_cast<double>(s.activeVoxels);
  state.counters["tiles"] = static_cast<double>(s.activeTiles);
  state.counters["memory_MiB"] = static_cast<double>(s.memoryBytes) / (1 << 20);
  state.counters["time_per_active_voxel"] = perActiveVoxel(static_cast<double>(s.activeVoxels));
}

// Voxel size for `across` voxels along the longest side of the source's bounding box.
inline double voxelSizeAcross(const AlphaFieldSource& source, double across) {
  Vec3 lo, hi;
  source.boundingBox(&lo, &hi);
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) / across;
}

// Times EnvelopeGrid::build(source, h) and sets the grid counters.
inline void timeGridBuild(benchmark::State& state, const AlphaFieldSource& source, double h) {
  EnvelopeGridStats stats;
  for (auto _ : state) {
    const EnvelopeGrid g = EnvelopeGrid::build(source, h);
    stats = g.stats();
    benchmark::DoNotOptimize(stats);
  }
  setGridCounters(state, stats);
}

// OpenVDB's own narrow-band sphere (half-width 3) at voxel size h, for the per-voxel comparison.
inline void timeLevelSetSphere(benchmark::State& state, float radius, const Vec3& centre, float h) {
  initializeOpenVdb();
  openvdb::Index64 active = 0;
  std::size_t memory = 0;
  for (auto _ : state) {
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        radius, openvdb::Vec3f(static_cast<float>(centre.x), static_cast<float>(centre.y), static_cast<float>(centre.z)), h);
    active = grid->activeVoxelCount();
    memory = static_cast<std::size_t>(grid->memUsage());
    benchmark::DoNotOptimize(active);
  }
  state.counters["active_voxels"] = static_cast<double>(active);
  state.counters["memory_MiB"] = static_cast<double>(memory) / (1 << 20);
  state.counters["time_per_active_voxel"] = perActiveVoxel(static_cast<double>(active));
}

}  // namespace fsdb::bench
