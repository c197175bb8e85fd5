#pragma once
// Random CSG graphs (query/structural/csg_graph.h) and leaf similarity matrices for property tests and the
// matching bench. Always seeded by the caller (std::mt19937), so failures reproduce.
#include <random>
#include <vector>

#include "query/structural/common_subgraph.h"
#include "query/structural/csg_graph.h"

namespace fsdb::testing {

inline CsgGraphOp randomOperation(std::mt19937& rng) {
  static const CsgGraphOp ops[] = {CsgGraphOp::Union, CsgGraphOp::Intersection, CsgGraphOp::Difference};
  return ops[std::uniform_int_distribution<int>(0, 2)(rng)];
}

// A random tree of `nodes` nodes (3 when nodes == 2: an operation has at least two children),
// operation nodes with random operations, leaves numbered 0..leafCount-1 in node order. Grown from a
// single leaf by turning a leaf into an operation with two leaf children, or giving an operation one
// more leaf child.
inline CsgGraph randomTree(std::mt19937& rng, int nodes) {
  CsgGraph g;
  g.nodes.resize(1);
  auto pick = [&](bool leaf) {
    std::vector<int> xs;
    for (size_t x = 0; x < g.nodes.size(); ++x)
      if ((g.nodes[x].op == CsgGraphOp::Leaf) == leaf) xs.push_back(int(x));
    return xs.empty() ? -1 : xs[std::uniform_int_distribution<size_t>(0, xs.size() - 1)(rng)];
  };
  while (int(g.nodes.size()) < nodes) {
    const int op = pick(false);
    const bool widen = op >= 0 && (nodes - int(g.nodes.size()) == 1 || std::bernoulli_distribution(0.35)(rng));
    if (widen) {
      g.nodes[size_t(op)].children.push_back(int(g.nodes.size()));
      g.nodes.emplace_back();
    } else {
      const int leaf = pick(true);
      g.nodes[size_t(leaf)].op = randomOperation(rng);
      for (int k = 0; k < 2; ++k) {
        g.nodes[size_t(leaf)].children.push_back(int(g.nodes.size()));
        g.nodes.emplace_back();
      }
    }
  }
  for (CsgGraphNode& n : g.nodes)
    if (n.op == CsgGraphOp::Leaf) n.leaf = g.leafCount++;
  return g;
}

// A random tree plus `extraEdges` edges from operation nodes to nodes that are not their ancestors
// (acyclic; shared nodes get several parents; a repeated child is allowed).
inline CsgGraph randomDag(std::mt19937& rng, int nodes, int extraEdges) {
  CsgGraph g = randomTree(rng, nodes);
  const int n = int(g.size());
  for (int e = 0, tries = 0; e < extraEdges && tries < 100; ++tries) {
    const int p = std::uniform_int_distribution<int>(0, n - 1)(rng);
    const int c = std::uniform_int_distribution<int>(0, n - 1)(rng);
    if (g.nodes[size_t(p)].op == CsgGraphOp::Leaf || c == g.root) continue;
    // c must not reach p (that would close a cycle).
    std::vector<int> stack{c};
    std::vector<char> seen(size_t(n), 0);
    bool reaches = false;
    while (!stack.empty() && !reaches) {
      const int x = stack.back();
      stack.pop_back();
      if (x == p) reaches = true;
      if (seen[size_t(x)]) continue;
      seen[size_t(x)] = 1;
      for (int y : g.nodes[size_t(x)].children) stack.push_back(y);
    }
    if (reaches) continue;
    g.nodes[size_t(p)].children.push_back(c);
    ++e;
  }
  return g;
}

// rows x cols similarities: often exactly 0, 0.5 or 1 (ties and inadmissible pairs), else uniform.
inline LeafSimilarityMatrix randomLeafSimilarity(std::mt19937& rng, int rows, int cols) {
  LeafSimilarityMatrix m;
  m.rows = rows;
  m.cols = cols;
  for (int i = 0; i < rows * cols; ++i) {
    const int k = std::uniform_int_distribution<int>(0, 5)(rng);
    m.values.push_back(k == 0 ? 0.0 : k == 1 ? 0.5 : k == 2 ? 1.0 : std::uniform_real_distribution<double>(0.05, 1)(rng));
  }
  return m;
}

}  // namespace fsdb::testing
