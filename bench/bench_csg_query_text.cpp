// Speed of reading query texts (query/structural/csg_query_text.h, query/linguistic/linguistic_query.h):
// a phrase list of n operands ("a sphere and a sphere and ...", one n-ary union) and a formula of n
// names ("cube + cube + ..."), n = 1000, 3000, 9999; and designers' phrasings of about 1000 and
// 10000 words: a CSG text with a request, a lead-in, fillers and "united with" joiners, and a
// linguistic bare description of comma-separated conditions, a CSG text of spatial relations ("a box, a
// cylinder about 2 units above it and a cone to its right, ..."), and printing that one back
// (parsed.read_as). All must grow linearly (each noun
// phrase once read from a single tokenisation); the goal is a 10,000-word text in under 1 s.
#include <benchmark/benchmark.h>

#include <string>

#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_print.h"
#include "query/structural/csg_query_text.h"

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

// About `words` words: "please show me shapes made of A united with B, please, and A united with B ...".
void BM_DesignersCsgText(benchmark::State& state) {
  const std::string pair = "a very bent cylinder united with a very sharp pyramid";  // 10 words
  std::string text = "please show me shapes made of " + pair;
  for (int words = 16; words + 12 <= state.range(0); words += 12) text += ", please, and " + pair;
  for (auto _ : state) {
    CsgQuery q = parseCsgQuery(text, Vocabulary::builtin(), {}, 1000000);
    benchmark::DoNotOptimize(q);
  }
  state.counters["words_per_s"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

// About `words` words: "show me something very round, slightly tapered, ..., please" (one and of conditions).
void BM_DesignersLinguisticText(benchmark::State& state) {
  std::string text = "show me something very round";
  for (int words = 5; words + 2 <= state.range(0); words += 2) text += words % 4 == 1 ? ", slightly tapered" : " and bent";
  text += ", please";
  for (auto _ : state) {
    LinguisticQuery q = parseLinguisticQuery(text, Vocabulary::builtin());
    benchmark::DoNotOptimize(q);
  }
  state.counters["words_per_s"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

// About `words` words of spatial relations: "a box, a cylinder about 2 units above it and a cone to
// its right, a box, ..." (each operand placed against the one before it).
std::string relationText(int64_t words) {
  const std::string group = "a box, a cylinder about 2 units above it and a cone to its right";  // 16 words
  std::string text = group;
  for (int64_t w = 16; w + 17 <= words; w += 17) text += ", " + group;
  return text;
}

void BM_DesignersRelationText(benchmark::State& state) {
  const std::string text = relationText(state.range(0));
  for (auto _ : state) {
    CsgQuery q = parseCsgQuery(text, Vocabulary::builtin(), {}, 1000000);
    benchmark::DoNotOptimize(q);
  }
  state.counters["words_per_s"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

// Printing the parse of the relation text back (parsed.read_as): query/structural/csg_query_print.h.
void BM_ReadAsRelationText(benchmark::State& state) {
  const CsgQuery q = parseCsgQuery(relationText(state.range(0)), Vocabulary::builtin(), {}, 1000000);
  for (auto _ : state) {
    std::string text = csgQueryText(q, Vocabulary::builtin());
    benchmark::DoNotOptimize(text);
  }
  state.counters["words_per_s"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_PhraseList)->Arg(1000)->Arg(3000)->Arg(9999)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignersCsgText)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignersLinguisticText)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DesignersRelationText)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadAsRelationText)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Formula)->Arg(1000)->Arg(3000)->Arg(9999)->Unit(benchmark::kMillisecond);

}  // namespace
