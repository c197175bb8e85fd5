// Speed of the structural match (query/structural/common_subgraph.h) per pair of graphs: random trees of 10,
// 20, 40, 80 nodes (the exact tree DP) and small DAGs (the branch and bound, default 100 ms budget;
// the "complete" counter is the fraction of pairs it finished). Random pairs, and a graph against a
// copy of itself with noisy leaf similarities (the case a search meets for its best results).
#include <benchmark/benchmark.h>

#include <random>

#include "query/structural/common_subgraph.h"
#include "query/structural/csg_graph.h"
#include "tests/testing/random_csg_graph.h"

namespace {

using namespace fsdb;

struct Pair {
  CsgGraph query, stored;
  LeafSimilarityMatrix leaves;
};

// 32 pairs per case, cycled, so one odd pair does not decide the time.
std::vector<Pair> pairs(int nodes, int extraEdges, bool copy) {
  std::mt19937 rng(uint32_t(nodes * 131 + extraEdges * 7 + copy));
  std::vector<Pair> out;
  for (int i = 0; i < 32; ++i) {
    Pair p;
    p.query = extraEdges ? testing::randomDag(rng, nodes, extraEdges) : testing::randomTree(rng, nodes);
    p.stored = copy ? p.query : extraEdges ? testing::randomDag(rng, nodes, extraEdges) : testing::randomTree(rng, nodes);
    p.leaves = testing::randomLeafSimilarity(rng, p.query.leafCount, p.stored.leafCount);
    if (copy)
      for (int k = 0; k < p.query.leafCount; ++k)
        p.leaves.values[size_t(k) * p.stored.leafCount + k] = std::uniform_real_distribution<double>(0.7, 1)(rng);
    out.push_back(std::move(p));
  }
  return out;
}

void run(benchmark::State& state, const std::vector<Pair>& ps) {
  size_t i = 0;
  double complete = 0, matched = 0, n = 0;
  for (auto _ : state) {
    const Pair& p = ps[i++ % ps.size()];
    const CommonSubgraph r = largestCommonSubgraph(p.query, p.stored, p.leaves);
    benchmark::DoNotOptimize(r.weight);
    complete += r.complete;
    matched += r.matchedNodes;
    ++n;
  }
  state.counters["complete"] = complete / n;
  state.counters["matched_nodes"] = matched / n;
}

void BM_TreePair(benchmark::State& state) {
  const auto ps = pairs(int(state.range(0)), 0, false);
  run(state, ps);
}
BENCHMARK(BM_TreePair)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

void BM_TreeCopy(benchmark::State& state) {
  const auto ps = pairs(int(state.range(0)), 0, true);
  run(state, ps);
}
BENCHMARK(BM_TreeCopy)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

// DAGs: n nodes with n / 4 extra parent edges.
void BM_DagPair(benchmark::State& state) {
  const int n = int(state.range(0));
  const auto ps = pairs(n, std::max(1, n / 4), false);
  run(state, ps);
}
BENCHMARK(BM_DagPair)->Arg(8)->Arg(12)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);

void BM_DagCopy(benchmark::State& state) {
  const int n = int(state.range(0));
  const auto ps = pairs(n, std::max(1, n / 4), true);
  run(state, ps);
}
BENCHMARK(BM_DagCopy)->Arg(8)->Arg(12)->Arg(16)->Arg(24)->Unit(benchmark::kMicrosecond);

// A small DAG query against one large stored DAG (a shape with many shared subtrees): the search
// stays within its budget (complete < 1 means the 100 ms budget cut it short).
void BM_DagLargeStored(benchmark::State& state) {
  std::mt19937 rng(99);
  Pair p;
  p.query = testing::randomDag(rng, 12, 3);
  p.stored = testing::randomDag(rng, int(state.range(0)), int(state.range(0)) / 4);
  p.leaves = testing::randomLeafSimilarity(rng, p.query.leafCount, p.stored.leafCount);
  run(state, {p});
}
BENCHMARK(BM_DagLargeStored)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);

}  // namespace
