// Speed of the fuzzy-number core: the operations a query or an evaluation repeats per
// parameter (cuts, arithmetic, similarity, defuzzification) and the fair-curve defuzzifier
// on a 180-sample membership over angles.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/fuzzy/defuzzify.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"

namespace {

using fsdb::FuzzyNumber;

const FuzzyNumber& tri() {
  static const FuzzyNumber a = FuzzyNumber::triangular(0.8, 1.0, 1.3);
  return a;
}
const FuzzyNumber& trap() {
  static const FuzzyNumber b = FuzzyNumber::trapezoidal(0.5, 0.9, 1.1, 2.0);
  return b;
}

void BM_AlphaCut(benchmark::State& state) {
  int step = 0;
  for (auto _ : state) {
    const double alpha = (step++ % 101) / 100.0;
    benchmark::DoNotOptimize(trap().alphaCut(alpha));
  }
}
BENCHMARK(BM_AlphaCut);

void BM_Add(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tri() + trap());
}
BENCHMARK(BM_Add);

void BM_Multiply(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tri() * trap());
}
BENCHMARK(BM_Multiply);

void BM_Similarity(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fsdb::similarity(tri(), trap()));
}
BENCHMARK(BM_Similarity);

void BM_Centroid(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fsdb::centroid(trap()));
}
BENCHMARK(BM_Centroid);

void BM_LocalMaxima180(benchmark::State& state) {
  std::vector<fsdb::Breakpoint> f;
  for (int deg = 0; deg < 180; ++deg) {
    const double mu = 0.67 * std::exp(-std::pow((deg - 73) / 10.0, 2)) +
                      0.13 * std::exp(-std::pow((deg - 146) / 5.0, 2)) +
                      0.10 * std::exp(-std::pow((deg - 4) / 3.0, 2)) +
                      0.05 * (1 + std::sin(deg * 0.3));  // ripples: many small maxima
    f.push_back({static_cast<double>(deg), mu});
  }
  for (auto _ : state) benchmark::DoNotOptimize(fsdb::localMaxima(f, 0.1));
}
BENCHMARK(BM_LocalMaxima180);

}  // namespace
