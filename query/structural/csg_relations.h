#pragma once
// Spatial relations of a CSG query text scored on a mapping (Zhang, Pham & Chen, §2.2 and §5):
// "a sphere on top of a cylinder" ranks a tree whose sphere sits on its cylinder above one whose
// sphere sits beside it, through the transform similarity of the match
// (query/structural/csg_similarity.h).
//
// Contract:
//  * A query leaf q with a relation (CsgQueryLeaf::relation: q's centre lies in a direction, at a
//    distance, from the centre of leaf r) has as its transform similarity
//    relationMembership(direction, distance, part of M(q), part of M(r))
//    (query/linguistic/linguistic_query.h) when both q and r are matched. When r is not, the
//    relation constrains nothing the stored tree has (the missing part already costs in the
//    component and structure terms), and q keeps the given transform similarity, as a description
//    without a relation does (1). So which of several equal single matches the subgraph search
//    keeps does not move the score. Other leaves keep the given transform similarity.
//  * The mapping is the largest common subgraph's: its objective has no transforms, for relations
//    as for absolute placements. Then each leaf in a relation (subject or reference), in query
//    order, may move to an unmatched stored leaf with the same parents and a leaf similarity at
//    least as high, when that raises the sum of the relation memberships. So among mappings the
//    paper's objective cannot tell apart (two equal spheres, one on the cylinder, one beside it),
//    the one the words describe is scored; the score is never lower than on the mapping found.
#include <vector>

#include "query/structural/common_subgraph.h"
#include "query/structural/csg_graph.h"
#include "query/structural/csg_query_text.h"

namespace fsdb {

// One relation of the query on a mapping, for the answer's explain.
struct RelationScore {
  int queryLeaf = 0;         // the related leaf (index into CsgQuery::leaves)
  int storedLeaf = -1;       // M(q): its stored leaf, -1 when unmatched
  int storedReference = -1;  // M(r), -1 when unmatched
  bool checked = false;      // both matched: `score` is the membership
  double score = 0;          // the membership; unchecked: the transform similarity q keeps (0 when q is unmatched)
};

// Whether any leaf of the query has a relation.
bool hasRelations(const CsgQuery& query);

// Scores the relations of `query` on `match` against `stored` (improving the mapping as the
// contract says: `match` may change, its weight and similarities kept consistent with
// `leafSimilarity`), and writes each related leaf's membership into `transform` at (q, M(q)).
// Returns one entry per related leaf, in leaf order.
std::vector<RelationScore> scoreRelations(const CsgQuery& query, const ShapeGraph& stored,
                                          const LeafSimilarityMatrix& leafSimilarity, CommonSubgraph& match,
                                          LeafSimilarityMatrix& transform);

}  // namespace fsdb
