#pragma once
// Upper bounds of the CSG score (query/structural/csg_similarity.h) of a stored graph against a query, so a
// top-k search (server/service/csg_search.h) can skip stored trees that cannot enter the results without
// running largestCommonSubgraph on them.
//
// Why they bound: the mapping of query/structural/common_subgraph.h is injective and label preserving, so
//  * matched operation nodes of each kind <= min(query count, stored count) of that kind, and
//    matched leaves <= min(query leaves, stored leaves)                       (signatureBound);
//  * with the leaf matrices: matched leaves pair only admissible leaves (sim > 0, >= leafThreshold),
//    each query leaf and each stored leaf at most once, so Σ matched sim <= min(Σ over query leaves
//    of their best admissible sim, Σ over stored leaves of theirs), the same for the transform
//    similarities, and matched leaves <= min(#query leaves with an admissible partner, #stored
//    leaves with one)                                                          (matrixBound);
// and components, transforms, structure are these sums over max(|leaves|) and max(|nodes|). Both
// bounds are >= scoreCommonSubgraph of every admissible mapping (tested on random graphs) and come
// with kBoundSlack added, so rounding in a different summation order never prunes a tie.
#include "query/structural/common_subgraph.h"
#include "query/structural/csg_graph.h"
#include "query/structural/csg_similarity.h"

namespace fsdb {

// Node counts of a graph by operation.
struct CsgSignature {
  int unions = 0, intersections = 0, differences = 0, leaves = 0;
  int nodes() const { return unions + intersections + differences + leaves; }
};
CsgSignature csgSignature(const CsgGraph& graph);

constexpr double kBoundSlack = 1e-9;

// From the node counts alone (no leaf similarity computed): in [0, 1 + kBoundSlack].
double signatureBound(const CsgSignature& query, const CsgSignature& stored, const CsgWeights& weights);

// With the leaf and transform similarity matrices (query leaves x stored leaves): <= signatureBound.
double matrixBound(const CsgSignature& query, const CsgSignature& stored, const LeafSimilarityMatrix& leafSimilarity,
                   const LeafSimilarityMatrix& transformSimilarity, double leafThreshold, const CsgWeights& weights);

}  // namespace fsdb
