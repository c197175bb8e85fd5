// See query/structural/csg_bound.h.
#include "query/structural/csg_bound.h"

#include <algorithm>
#include <vector>

namespace fsdb {
namespace {

int matchedOperationsBound(const CsgSignature& q, const CsgSignature& s) {
  return std::min(q.unions, s.unions) + std::min(q.intersections, s.intersections) +
         std::min(q.differences, s.differences);
}

// The score formula of scoreCommonSubgraph on bounds of its sums.
double combine(const CsgSignature& q, const CsgSignature& s, double leafSum, double transformSum, double matched,
               const CsgWeights& w) {
  const double leaves = std::max(q.leaves, s.leaves);
  const double nodes = std::max(q.nodes(), s.nodes());
  const double components = leaves > 0 ? leafSum / leaves : 0;
  const double transforms = leaves > 0 ? transformSum / leaves : 0;
  const double structure = nodes > 0 ? matched / nodes : 0;
  const double total = w.components + w.transforms + w.structure;
  const double score = (w.components * components + w.transforms * transforms + w.structure * structure) / total;
  return std::min(1.0, score) + kBoundSlack;
}

}  // namespace

CsgSignature csgSignature(const CsgGraph& graph) {
  CsgSignature out;
  for (const CsgGraphNode& n : graph.nodes) switch (n.op) {
      case CsgGraphOp::Union: ++out.unions; break;
      case CsgGraphOp::Intersection: ++out.intersections; break;
      case CsgGraphOp::Difference: ++out.differences; break;
      case CsgGraphOp::Leaf: ++out.leaves; break;
    }
  return out;
}

double signatureBound(const CsgSignature& query, const CsgSignature& stored, const CsgWeights& weights) {
  const double leaves = std::min(query.leaves, stored.leaves);
  return combine(query, stored, leaves, leaves, matchedOperationsBound(query, stored) + leaves, weights);
}

double matrixBound(const CsgSignature& query, const CsgSignature& stored, const LeafSimilarityMatrix& leafSimilarity,
                   const LeafSimilarityMatrix& transformSimilarity, double leafThreshold, const CsgWeights& weights) {
  const int rows = leafSimilarity.rows, cols = leafSimilarity.cols;
  std::vector<double> rowSim(rows, 0), colSim(cols, 0), rowTransform(rows, 0), colTransform(cols, 0);
  std::vector<char> rowAdmissible(rows, 0), colAdmissible(cols, 0);
  for (int q = 0; q < rows; ++q)
    for (int s = 0; s < cols; ++s) {
      const double sim = leafSimilarity.at(q, s);
      if (!(sim > 0) || sim < leafThreshold) continue;
      const double t = transformSimilarity.at(q, s);
      rowSim[q] = std::max(rowSim[q], sim);
      colSim[s] = std::max(colSim[s], sim);
      rowTransform[q] = std::max(rowTransform[q], t);
      colTransform[s] = std::max(colTransform[s], t);
      rowAdmissible[q] = colAdmissible[s] = 1;
    }
  const auto sum = [](const auto& v) {
    double out = 0;
    for (auto x : v) out += x;
    return out;
  };
  const double leafSum = std::min(sum(rowSim), sum(colSim));
  const double transformSum = std::min(sum(rowTransform), sum(colTransform));
  const double matchedLeaves = std::min(sum(rowAdmissible), sum(colAdmissible));
  return combine(query, stored, leafSum, transformSum, matchedOperationsBound(query, stored) + matchedLeaves, weights);
}

}  // namespace fsdb
