// Speed of the alpha field of one fuzzy superquadric part (geometry/field/fuzzy_part_field.h): ns
// per levelsAt at points inside, outside and on the boundary band, for a crisp unit sphere,
// a fuzzy sphere (a1 = tri(0.8, 1, 1.2)) and a fuzzy bent, tapered, twisted, placed part (every
// value spread by a few percent); and ns per boundsOver on blocks of edge 0.1 around the part.
// Points and blocks are fixed (seed 1). BM_FuzzyDeformationsGrid: the part with only its four
// deformation values fuzzy, N = 64 ... 512. BM_DeformedPartGrid: EnvelopeGrid::build of the fuzzy
// deformed part with N = 32, 64 or 128 voxels across its bounding box, through levelsAt (impl 1) or
// the previous bisection reference::bisectionLevelsAt (impl 0, at 32), one iteration each.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "bench/grid_bench.h"
#include "geometry/field/fuzzy_part_field.h"
#include "tests/testing/fuzzy_bench_part.h"

namespace fsdb {
namespace {

FuzzyPart crispSphere() { return FuzzyPart{}; }

FuzzyPart fuzzySphere() {
  FuzzyPart part;
  part.a1 = FuzzyNumber::triangular(0.8, 1.0, 1.2);
  return part;
}

FuzzyPart fuzzyDeformed() { return testing::allValuesFuzzyPart(); }

// A "fuzzy bent, tapered, twisted part": the same part with only its four deformation
// values fuzzy (taper kx, ky, bend kv, twist t: "a slightly bent, tapered, twisted bar"), the
// other ten crisp at the cores above.
FuzzyPart fuzzyDeformations() {
  FuzzyPart part = fuzzyDeformed();
  for (FuzzyNumber* v : {&part.eps1, &part.eps2, &part.a1, &part.a2, &part.a3, &part.tx, &part.ty,
                         &part.tz, &part.deg, &part.scale}) {
    const double core = v->core().lo;
    *v = FuzzyNumber::triangular(core, core, core);
  }
  return part;
}

FuzzyPart makePart(int which) {
  return which == 0 ? crispSphere() : which == 1 ? fuzzySphere() : fuzzyDeformed();
}

// Points of one class: inside S(θ) for every θ in P(0) (l = 0), outside for every θ (u = 0), or the
// band in between (where the bisections run).
std::vector<Vec3> samplePoints(const FuzzyPartField& field, int cls) {
  Vec3 lo, hi;
  field.boundingBox(&lo, &hi);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points;
  for (int tries = 0; tries < 20000 && points.size() < 64; ++tries) {
    const Vec3 p{lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
                 lo.z + (hi.z - lo.z) * u(rng)};
    const int c = field.necessarilyInside(p, 0.0) ? 0 : !field.possiblyInside(p, 0.0) ? 1 : 2;
    if (c == cls) points.push_back(p);
  }
  return points;
}

// ns per call of `levels(field, p)` over the sampled points, with the exhaustions it caused.
// state.range(0): part (0 crisp sphere, 1 fuzzy sphere, 2 fuzzy deformed); state.range(1): point
// class (0 inside, 1 outside, 2 boundary band).
template <typename Levels>
void timeLevels(benchmark::State& state, Levels levels) {
  const FuzzyPartField field(makePart(static_cast<int>(state.range(0))));
  const std::vector<Vec3> points = samplePoints(field, static_cast<int>(state.range(1)));
  if (points.empty()) {
    state.SkipWithError("no points of this class");
    return;
  }
  const std::uint64_t before = field.budgetExhaustions();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(levels(field, points[i]));
    if (++i == points.size()) i = 0;
  }
  state.counters["exhausted"] = static_cast<double>(field.budgetExhaustions() - before);
}

void BM_LevelsAt(benchmark::State& state) {
  timeLevels(state, [](const FuzzyPartField& f, const Vec3& p) { return f.levelsAt(p); });
}
BENCHMARK(BM_LevelsAt)
    ->ArgNames({"part", "class"})
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->Unit(benchmark::kNanosecond);

// The same through the previous bisection (reference::bisectionLevelsAt), for before/after in one
// run; its exhaustion counter counts bisection decisions, levelsAt's counts searches (two at most).
void BM_LevelsAtBisection(benchmark::State& state) {
  timeLevels(state, reference::bisectionLevelsAt);
}
BENCHMARK(BM_LevelsAtBisection)
    ->ArgNames({"part", "class"})
    ->ArgsProduct({{1, 2}, {0, 1, 2}})
    ->Unit(benchmark::kNanosecond);

void BM_BoundsOver(benchmark::State& state) {
  const FuzzyPartField field(makePart(static_cast<int>(state.range(0))));
  Vec3 lo, hi;
  field.boundingBox(&lo, &hi);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> corners(1024);
  for (auto& c : corners)
    c = {lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
         lo.z + (hi.z - lo.z) * u(rng)};
  const Vec3 edge{0.1, 0.1, 0.1};
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(field.boundsOver(corners[i], corners[i] + edge));
    if (++i == corners.size()) i = 0;
  }
}
BENCHMARK(BM_BoundsOver)->ArgName("part")->DenseRange(0, 2)->Unit(benchmark::kNanosecond);

// The part's field with levelsAt replaced by the previous bisection, for before/after timings.
class BisectionField : public AlphaFieldSource {
 public:
  explicit BisectionField(const FuzzyPartField& field) : field_(field) {}
  AlphaLevels levelsAt(const Vec3& p) const override {
    return reference::bisectionLevelsAt(field_, p);
  }
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override {
    return field_.boundsOver(lo, hi);
  }
  void boundingBox(Vec3* lo, Vec3* hi) const override { field_.boundingBox(lo, hi); }

 private:
  const FuzzyPartField& field_;
};

// state.range(0): voxels across the largest side of the bounding box; state.range(1): 0 the
// bisection reference, 1 levelsAt.
void BM_DeformedPartGrid(benchmark::State& state) {
  const FuzzyPartField field(fuzzyDeformed());
  const BisectionField bisection(field);
  const double h = bench::voxelSizeAcross(field, static_cast<double>(state.range(0)));
  const AlphaFieldSource& source =
      state.range(1) == 0 ? static_cast<const AlphaFieldSource&>(bisection) : field;
  const std::uint64_t before = field.budgetExhaustions();
  bench::timeGridBuild(state, source, h);
  state.counters["exhausted"] = static_cast<double>(field.budgetExhaustions() - before);
}
// The bisection reference only at 32 (minutes beyond); levelsAt up to 128 (about two minutes on
// the 2-core machine; 256 would take about ten times as long).
BENCHMARK(BM_DeformedPartGrid)
    ->ArgNames({"across", "impl"})
    ->Args({32, 0})
    ->Args({32, 1})
    ->Args({64, 1})
    ->Args({128, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The part with only its deformation values fuzzy at N = 64 ... 512, one iteration each.
void BM_FuzzyDeformationsGrid(benchmark::State& state) {
  const FuzzyPartField field(fuzzyDeformations());
  const double h = bench::voxelSizeAcross(field, static_cast<double>(state.range(0)));
  const std::uint64_t before = field.budgetExhaustions();
  bench::timeGridBuild(state, field, h);
  state.counters["exhausted"] = static_cast<double>(field.budgetExhaustions() - before);
}
BENCHMARK(BM_FuzzyDeformationsGrid)
    ->ArgName("across")
    ->RangeMultiplier(2)
    ->Range(64, 512)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace fsdb
