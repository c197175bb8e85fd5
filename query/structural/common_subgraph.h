#pragma once
// The largest common subgraph of two CSG graphs (query/structural/csg_graph.h), the mapping behind CSG
// similarity (Zhang, Pham & Chen, §5: "the best mapping between the query tree and the stored
// tree"; Shearer, Bunke, Venkatesh 2001 for the maximum common subgraph as a graph similarity).
//
// Objective (exactly what `weight` is): over all maps M from a set of query nodes into the stored
// nodes that are
//   * injective;
//   * label preserving: an operation node onto a node of the same operation (weight 1), a leaf onto a
//     leaf q -> s with sim = leafSimilarity.at(q.leaf, s.leaf) > 0 and sim >= leafThreshold (weight sim);
//   * induced: for matched u, v the number of edges u->v in the query equals the number of edges
//     M(u)->M(v) in the stored graph (an edge present on one side only forbids matching both ends);
//   * role preserving: an edge u->v matched onto M(u)->M(v) of a difference keeps its role: minuend
//     onto minuend, subtrahend onto subtrahend;
//   * connected: the matched query nodes form a connected subgraph (edges taken undirected), so the
//     common part may be rooted anywhere, not only at the roots;
// maximise  weight = Σ over matched operation nodes of 1 + Σ over matched leaves of sim.
// The empty map (weight 0) is always admissible.
//
// Algorithms:
//  * both graphs trees: exact, polynomial. For every node pair (u, v) with equal labels, best(u, v) =
//    label weight + the maximum-weight bipartite matching (query/structural/assignment.h) of u's children against
//    v's children with weights max(0, best(child pair)); for a difference the minuends pair only with
//    each other and the subtrahends are matched as an unordered set. The answer is the max over all
//    pairs (the common subtree may be rooted at any pair). O(|Q|·|S|·d³) for degree d.
//  * otherwise (a DAG on either side): McSplit-style branch and bound (McCreesh, Prosser, Trimble 2017:
//    label classes of unmatched vertices refined by adjacency to each new pair, bound = current
//    weight + Σ over classes of the best possible gain of min(|class in Q|, |class in S|) vertices),
//    adapted to weights and to connectedness; stops after timeBudgetMs with complete = false and the
//    best map found so far.
// Cost: the tree DP keeps one value per node pair (|Q|·|S| doubles) and runs one assignment per
// label-compatible pair; the search keeps the graphs' edges (no node-pair tables) and O(|Q| + |S|)
// per search node. Callers bound the query size (docs/api.md §4 node limit).
#include <cstddef>
#include <functional>
#include <vector>

namespace fsdb {

struct CsgGraph;  // query/structural/csg_graph.h

// values[q * cols + s] in [0,1]: similarity of query leaf q and stored leaf s.
struct LeafSimilarityMatrix {
  int rows = 0, cols = 0;
  std::vector<double> values;
  double at(int q, int s) const { return values[size_t(q) * cols + s]; }
};

struct CommonSubgraphOptions {
  double leafThreshold = 0.0;  // leaves match only when similarity > 0 and >= leafThreshold
  double timeBudgetMs = 100;   // general (DAG) search only; the tree algorithm is exact and polynomial
};

// `poll`, when set, is called now and then (about every 4096 node pairs of the tree DP, every row of
// its assignments, every clock read of the DAG search); it may throw to abandon the whole match (the
// caller's query time limit: a tree DP of two 10000-node unions is exact but not quick).
using CommonSubgraphPoll = std::function<void()>;

struct NodeMatch {
  int queryNode = 0;
  int storedNode = 0;
  double similarity = 1;  // operation nodes: 1; leaves: the leaf similarity
};

struct CommonSubgraph {
  std::vector<NodeMatch> matches;  // the node mapping, sorted by queryNode
  double weight = 0;               // objective: Σ matched operation nodes (1 each) + Σ matched leaf similarities
  int matchedNodes = 0, matchedLeaves = 0;
  bool complete = true;            // false when the DAG search hit timeBudgetMs (best found so far)
};

// The maximum-weight common connected subgraph as defined above. leafSimilarity must be
// query.leafCount x stored.leafCount, every leaf's payload index below leafCount and every child
// index a node of its graph (invalid_parameter, path "leafSimilarity" or "graph", otherwise).
CommonSubgraph largestCommonSubgraph(const CsgGraph& query, const CsgGraph& stored,
                                     const LeafSimilarityMatrix& leafSimilarity,
                                     const CommonSubgraphOptions& options = {},
                                     const CommonSubgraphPoll& poll = {});

// The same objective solved by the general branch and bound even on trees (tests compare it with
// the tree DP; callers use largestCommonSubgraph).
CommonSubgraph largestCommonSubgraphSearch(const CsgGraph& query, const CsgGraph& stored,
                                           const LeafSimilarityMatrix& leafSimilarity,
                                           const CommonSubgraphOptions& options = {},
                                     const CommonSubgraphPoll& poll = {});

}  // namespace fsdb
