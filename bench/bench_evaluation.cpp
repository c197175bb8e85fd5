// Speed of evaluating superquadric parts and CSG assemblies on envelope grids: the
// whole path of POST /evaluate after parsing: FuzzyPartField / CsgField sources sampled by
// EnvelopeGrid::build (block pruning with interval bounds, TBB), at N voxels along the longest
// side of the bounding box, for
//   - a crisp sphere part (radius 1),
//   - a 10-part fuzzy CSG assembly (union of 8 fuzzy balls and rods minus 2 holes),
// and, for scale, OpenVDB's createLevelSetSphere at the sphere's voxel size. The fuzzy bent,
// tapered, twisted part (every value fuzzy) is timed on grids by bench_fuzzy_part_field
// (BM_DeformedPartGrid).
// Counters: active voxels, tiles, memory of both grids, time per active voxel.
// Goals: 256/128 time ratio <= 4.5, per-active-voxel cost <= 3x
// createLevelSetSphere, the 10-part assembly at 256 in under 1 s.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

#include "bench/grid_bench.h"
#include "geometry/field/csg_field.h"
#include "geometry/field/fuzzy_part_field.h"

namespace fsdb {
namespace {

FuzzyNumber fuzzy(double m, double relSpread) {
  const double s = std::max(std::fabs(m) * relSpread, 1e-3);
  return FuzzyNumber::triangular(m - s, m, m + s);
}

std::shared_ptr<const AlphaFieldSource> crispSphere() {
  FuzzyPart p;  // unit sphere
  return std::make_shared<FuzzyPartField>(p);
}

std::shared_ptr<const AlphaFieldSource> ball(double x, double y, double z, double r, double spread) {
  FuzzyPart p;
  p.a1 = fuzzy(r, spread);
  p.tx = FuzzyNumber::crisp(x);
  p.ty = FuzzyNumber::crisp(y);
  p.tz = FuzzyNumber::crisp(z);
  return std::make_shared<FuzzyPartField>(p);
}

std::shared_ptr<const AlphaFieldSource> rod(double x, double y, double r, double half, double spread) {
  FuzzyPart p;
  p.eps1 = FuzzyNumber::crisp(0.2);  // a rounded cylinder along z
  p.a1 = fuzzy(r, spread);
  p.a3 = FuzzyNumber::crisp(half / r);
  p.tx = FuzzyNumber::crisp(x);
  p.ty = FuzzyNumber::crisp(y);
  return std::make_shared<FuzzyPartField>(p);
}

std::shared_ptr<const AlphaFieldSource> tenPartAssembly() {
  std::vector<std::shared_ptr<const AlphaFieldSource>> body = {
      ball(0, 0, 0, 1.0, 0.05),        ball(1.2, 0, 0, 0.6, 0.05),  ball(-1.2, 0, 0, 0.6, 0.05),
      ball(0, 1.2, 0, 0.6, 0.05),      ball(0, -1.2, 0, 0.6, 0.05), rod(0.8, 0.8, 0.25, 1.2, 0.05),
      rod(-0.8, -0.8, 0.25, 1.2, 0.05), rod(0.8, -0.8, 0.25, 1.2, 0.05)};
  auto united = std::make_shared<CsgField>(CsgOp::kUnion, body);
  return std::make_shared<CsgField>(
      CsgOp::kDifference, std::vector<std::shared_ptr<const AlphaFieldSource>>{
                              united, ball(0, 0, 0.9, 0.4, 0.05), ball(0, 0, -0.9, 0.4, 0.05)});
}

void buildSource(benchmark::State& state, const AlphaFieldSource& source) {
  bench::timeGridBuild(state, source, bench::voxelSizeAcross(source, static_cast<double>(state.range(0))));
}

void BM_CrispSpherePart(benchmark::State& state) { buildSource(state, *crispSphere()); }
void BM_TenPartAssembly(benchmark::State& state) { buildSource(state, *tenPartAssembly()); }

// The crisp sphere's bounding box is padded by the field; use the same voxel size.
void BM_OpenVdbLevelSetSphere(benchmark::State& state) {
  const double h = bench::voxelSizeAcross(*crispSphere(), static_cast<double>(state.range(0)));
  bench::timeLevelSetSphere(state, 1.0f, Vec3{0, 0, 0}, static_cast<float>(h));
}

// Resolutions: 64..512 for the sphere and the assembly (its parts are monotone in
// their one fuzzy value almost everywhere, so the corner shortcut of fuzzy_part_field.h answers
// most band voxels without a search).
BENCHMARK(BM_CrispSpherePart)->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenVdbLevelSetSphere)->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TenPartAssembly)->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace fsdb
