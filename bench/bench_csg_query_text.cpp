// Speed of reading CSG query texts (query/structural/csg_query_text.h): a phrase list of n operands ("a sphere
// and a sphere and ...", one n-ary union) and a formula of n names ("cube + cube + ..."), n = 1000,
// 3000, 9999. Both must grow linearly in n (each noun phrase once read from a single tokenisation).
#include <benchmark/benchmark.h>

#include <string>

#include "query/structural/csg_query_text.h"
#include "query/linguistic/vocabulary.h"

namespace {

using namespace fsdb;

std::string repeated(const std::string& first, const std::string& link, int n) {
  std::string text = first;
  for (int i = 1; i < n; ++i) text += link + first;
  return text;
}

void parse(benchmark::State& state, const std::string& text) {
  for (auto _ : state) {
    CsgQuery q = parseCsgQuery(text, Vocabulary::builtin(), {}, 1000000);
    benchmark::DoNotOptimize(q);
  }
  state.counters["operands_per_s"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_PhraseList(benchmark::State& state) { parse(state, repeated("a sphere", " and ", int(state.range(0)))); }
void BM_Formula(benchmark::State& state) { parse(state, repeated("cube", " + ", int(state.range(0)))); }

BENCHMARK(BM_PhraseList)->Arg(1000)->Arg(3000)->Arg(9999)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Formula)->Arg(1000)->Arg(3000)->Arg(9999)->Unit(benchmark::kMillisecond);

}  // namespace
