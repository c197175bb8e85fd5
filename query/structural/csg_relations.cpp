// See query/structural/csg_relations.h.
#include "query/structural/csg_relations.h"

#include <algorithm>
#include <unordered_set>

#include "query/linguistic/linguistic_query.h"

namespace fsdb {

bool hasRelations(const CsgQuery& query) {
  return std::any_of(query.leaves.begin(), query.leaves.end(),
                     [](const CsgQueryLeaf& l) { return l.relation.has_value(); });
}

std::vector<RelationScore> scoreRelations(const CsgQuery& query, const ShapeGraph& stored,
                                          const LeafSimilarityMatrix& leafSimilarity, CommonSubgraph& match,
                                          LeafSimilarityMatrix& transform) {
  std::vector<RelationScore> out;
  if (!hasRelations(query)) return out;
  const CsgGraph& qg = query.graph;
  const CsgGraph& sg = stored.graph;
  const size_t leaves = query.leaves.size();

  // The leaf mapping: query leaf -> stored leaf, and where each query leaf's NodeMatch is.
  std::vector<int> storedOf(leaves, -1);
  std::vector<size_t> matchOf(leaves, match.matches.size());
  std::unordered_set<int> usedNodes;
  for (size_t i = 0; i < match.matches.size(); ++i) {
    const NodeMatch& m = match.matches[i];
    usedNodes.insert(m.storedNode);
    const CsgGraphNode& qn = qg.nodes[size_t(m.queryNode)];
    if (qn.op != CsgGraphOp::Leaf) continue;
    storedOf[size_t(qn.leaf)] = sg.nodes[size_t(m.storedNode)].leaf;
    matchOf[size_t(qn.leaf)] = i;
  }

  // The relations each leaf takes part in (as subject or reference).
  std::vector<std::vector<size_t>> involving(leaves);
  for (size_t q = 0; q < leaves; ++q) {
    if (!query.leaves[q].relation) continue;
    involving[q].push_back(q);
    const size_t r = query.leaves[q].relation->to;
    if (r != q) involving[r].push_back(q);
  }
  // Unchecked relations count 0 here: moves only ever raise the sum of the checked ones.
  const auto membership = [&](size_t q) {
    const CsgRelation& rel = *query.leaves[q].relation;
    const int s = storedOf[q], r = storedOf[rel.to];
    if (s < 0 || r < 0 || s == r) return 0.0;
    return relationMembership(rel.direction, rel.distance, stored.leaves[size_t(s)].part,
                              stored.leaves[size_t(r)].part);
  };
  const auto localSum = [&](size_t q) {
    double sum = 0;
    for (size_t k : involving[q]) sum += membership(k);
    return sum;
  };

  // Moves within the paper's ties: an unmatched sibling leaf with the same parents and at least
  // the same leaf similarity keeps the mapping admissible (a leaf's only edges are its parents')
  // and its objective no lower.
  const std::vector<std::vector<int>> parents = sg.parents();
  const auto sortedParents = [&](int node) {
    std::vector<int> p = parents[size_t(node)];
    std::sort(p.begin(), p.end());
    return p;
  };
  for (size_t q = 0; q < leaves; ++q) {
    if (involving[q].empty() || storedOf[q] < 0) continue;
    NodeMatch& m = match.matches[matchOf[q]];
    const std::vector<int> ps = sortedParents(m.storedNode);
    if (ps.empty()) continue;  // the stored root: nothing beside it
    const int originalLeaf = storedOf[q];
    const double originalSim = leafSimilarity.at(int(q), originalLeaf);
    double best = localSum(q);
    int bestNode = -1;
    for (int v : sg.nodes[size_t(ps.front())].children) {
      const CsgGraphNode& vn = sg.nodes[size_t(v)];
      if (vn.op != CsgGraphOp::Leaf || usedNodes.count(v) || leafSimilarity.at(int(q), vn.leaf) < originalSim ||
          sortedParents(v) != ps)
        continue;
      storedOf[q] = vn.leaf;
      const double sum = localSum(q);
      if (sum > best + 1e-12) {
        best = sum;
        bestNode = v;
      }
    }
    storedOf[q] = originalLeaf;
    if (bestNode < 0) continue;
    usedNodes.erase(m.storedNode);
    usedNodes.insert(bestNode);
    m.storedNode = bestNode;
    storedOf[q] = sg.nodes[size_t(bestNode)].leaf;
    const double sim = leafSimilarity.at(int(q), storedOf[q]);
    match.weight += sim - m.similarity;
    m.similarity = sim;
  }

  for (size_t q = 0; q < leaves; ++q) {
    if (!query.leaves[q].relation) continue;
    RelationScore r;
    r.queryLeaf = int(q);
    r.storedLeaf = storedOf[q];
    r.storedReference = storedOf[query.leaves[q].relation->to];
    r.checked = r.storedLeaf >= 0 && r.storedReference >= 0;
    if (r.checked) {
      r.score = membership(q);
      transform.values[q * size_t(transform.cols) + size_t(r.storedLeaf)] = r.score;
    } else if (r.storedLeaf >= 0) {
      r.score = transform.at(int(q), r.storedLeaf);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace fsdb
