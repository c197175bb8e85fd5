// Meshing a crisp unit sphere (geometry/voxel/smooth_mesh.h) at 128 and 256 voxels across:
// the smooth mesh (voxel mesh, then every vertex moved onto the surface by bisection on the
// exact field), the voxel mesh it starts from (extractMesh: volumeToMesh on the indicator), and
// OpenVDB's own volumeToMesh of a narrow-band level-set sphere of the same voxel size
// (createLevelSetSphere, half-width 3; only the meshing is timed, as for the others). Counters:
// triangles, the worst and mean vertex distance to the sphere in voxels, the volume error in %.
#include <benchmark/benchmark.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <map>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/voxel/envelope_grid.h"
#include "geometry/voxel/smooth_mesh.h"

namespace {

using namespace fsdb;

constexpr double kPi = 3.14159265358979323846;

const FuzzyPartField& sphere() {
  static const FuzzyPartField field(FuzzyPart::fromCrisp(PlacedSuperquadric{}));
  return field;
}

const EnvelopeGrid& gridAt(int resolution) {
  static std::map<int, EnvelopeGrid> grids;
  auto it = grids.find(resolution);
  if (it == grids.end()) it = grids.emplace(resolution, EnvelopeGrid::build(sphere(), 2.0 / resolution)).first;
  return it->second;
}

void report(benchmark::State& state, const std::vector<Vec3>& vertices, size_t triangles, double volume, double h) {
  double worst = 0, sum = 0;
  for (const Vec3& v : vertices) {
    const double d = std::fabs(norm(v) - 1.0) / h;
    worst = std::max(worst, d);
    sum += d;
  }
  state.counters["triangles"] = double(triangles);
  state.counters["worst_voxels"] = worst;
  state.counters["mean_voxels"] = sum / double(vertices.size());
  state.counters["volume_error_pct"] = 100.0 * (volume - 4.0 / 3.0 * kPi) / (4.0 / 3.0 * kPi);
}

double volumeOf(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6.0;
  return v;
}

void BM_SmoothMesh(benchmark::State& state) {
  const EnvelopeGrid& grid = gridAt(int(state.range(0)));
  TriangleMesh mesh;
  for (auto _ : state) {
    mesh = extractSmoothMesh(grid, sphere(), 1.0, EnvelopeBound::kUpper);
    benchmark::DoNotOptimize(mesh);
  }
  report(state, mesh.vertices, mesh.triangles.size(), volumeOf(mesh), grid.voxelSize());
}

void BM_VoxelMesh(benchmark::State& state) {
  const EnvelopeGrid& grid = gridAt(int(state.range(0)));
  TriangleMesh mesh;
  for (auto _ : state) {
    mesh = extractMesh(grid, 1.0, EnvelopeBound::kUpper);
    benchmark::DoNotOptimize(mesh);
  }
  report(state, mesh.vertices, mesh.triangles.size(), volumeOf(mesh), grid.voxelSize());
}

void BM_OpenVdbLevelSetSphere(benchmark::State& state) {
  openvdb::initialize();
  const double h = 2.0 / double(state.range(0));
  const auto grid =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(1.0f, openvdb::Vec3f(0, 0, 0), float(h), 3.0f);
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec4I> quads;
  for (auto _ : state) {
    points.clear();
    quads.clear();
    openvdb::tools::volumeToMesh(*grid, points, quads, 0.0);
    benchmark::DoNotOptimize(points);
  }
  TriangleMesh mesh;
  for (const auto& p : points) mesh.vertices.push_back({p.x(), p.y(), p.z()});
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  report(state, mesh.vertices, mesh.triangles.size(), std::fabs(volumeOf(mesh)), h);
}

BENCHMARK(BM_SmoothMesh)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelMesh)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenVdbLevelSetSphere)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
