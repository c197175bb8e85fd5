// Speed of the linguistic core per part and per query: descriptor values of a crisp and of a
// fuzzy part (describePart: what indexing a stored part costs), parsing a query, and scoring one
// part's values against it (scoreDescriptors: what each candidate of a search costs).
#include <benchmark/benchmark.h>

#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/linguistic/vocabulary.h"

namespace {

using namespace fsdb;

const FuzzyPart& crispPart() {
  static const FuzzyPart p = parsePart({{"params", {{"a1", 1}, {"a3", 2}, {"eps1", 0.1}, {"kv", 0.2}}}}, "");
  return p;
}

// Every shape parameter fuzzy, as in bench_fuzzy_part_field.
const FuzzyPart& fuzzyPart() {
  static const FuzzyPart p = parsePart(
      {{"params",
        {{"eps1", {{"tri", {0.5, 1, 2.5}}}}, {"eps2", {{"tri", {0.1, 0.2, 0.4}}}}, {"a1", {{"tri", {0.8, 1, 1.2}}}},
         {"a2", {{"tri", {0.5, 1, 3}}}}, {"a3", {{"tri", {0.8, 1.5, 2}}}}, {"kx", {{"tri", {-0.5, 0, 0.2}}}},
         {"ky", {{"tri", {-0.2, 0, 0.2}}}}, {"kv", {{"tri", {-0.2, 0.1, 0.3}}}}, {"t", {{"tri", {0.5, 1, 2}}}}}}},
      "");
  return p;
}

void BM_DescribeCrispPart(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(describePart(crispPart()));
}
BENCHMARK(BM_DescribeCrispPart);

void BM_DescribeFuzzyPart(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(describePart(fuzzyPart()));
}
BENCHMARK(BM_DescribeFuzzyPart);

const char* kQuery = "find a very bent cylinder that is not twisted and slightly tapered";

void BM_ParseQuery(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(parseLinguisticQuery(kQuery, Vocabulary::builtin()));
}
BENCHMARK(BM_ParseQuery);

void BM_ScoreCrispValues(benchmark::State& state) {
  const LinguisticQuery q = parseLinguisticQuery(kQuery, Vocabulary::builtin());
  const auto values = describePart(crispPart());
  for (auto _ : state) benchmark::DoNotOptimize(scoreDescriptors(q, values));
}
BENCHMARK(BM_ScoreCrispValues);

void BM_ScoreFuzzyValues(benchmark::State& state) {
  const LinguisticQuery q = parseLinguisticQuery(kQuery, Vocabulary::builtin());
  const auto values = describePart(fuzzyPart());
  for (auto _ : state) benchmark::DoNotOptimize(scoreDescriptors(q, values));
}
BENCHMARK(BM_ScoreFuzzyValues);

}  // namespace
