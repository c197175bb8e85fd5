#pragma once
// CSG similarity (Zhang, Pham & Chen, §5; docs/api.md §5): a stored tree against a query tree
// ranks by
//   w1·component similarity + w2·transform similarity + w3·structure similarity
// over the best mapping between the two trees, the largest common subgraph (query/structural/common_subgraph.h).
//
// Choices (documented here, tested in tests/query/structural/csg_similarity_test.cpp):
//  * structure  = matchedNodes / max(|query|, |stored|): the maximum-common-subgraph distance of Bunke
//    and Shearer as a similarity (Shearer, Bunke, Venkatesh 2001), counting nodes of the mapping.
//  * components = Σ matched leaf similarity / max(query leaves, stored leaves): unmatched leaves on the
//    larger side count 0, so extra parts in either tree lower the score.
//  * transforms = Σ transformSimilarity(q, s) over matched leaf pairs / max(query leaves, stored leaves),
//    read from the caller's matrix (a text leaf without placement is the caller's business).
//  * score = (w1·components + w2·transforms + w3·structure) / (w1 + w2 + w3), in [0,1]. Each term is
//    1 only when every node of both graphs is matched (so |query| = |stored|) and every matched leaf
//    pair has similarity 1 and transform similarity 1: the score is 1 only for an exact match (with
//    every weight > 0; a zero weight drops its term). Weights must be finite and >= 0 with a positive
//    sum, else invalid_parameter at path "weights".
//  * partSimilarity = min over the 9 shape parameters (eps1, eps2, a1, a2, a3, kx, ky, kv, t) of
//    the fuzzy similarity S(A,B) (geometry/fuzzy/fuzzy_similarity.h); min is the conjunction
//    docs/api.md §5 uses for conditions. Placement is not part of it (that is transformSimilarity).
//  * transformSimilarity = min of S on translate x, y, z, on scale, and on the rotation: S(deg_a, deg_b)
//    times |axis_a · axis_b| (b's axis flipped to agree with a's, negating its angle; a rotation by a
//    crisp 0 is the identity whatever its axis, and then only the other angle against 0 counts).
//    Degrees compare as written (no wrap-around at 360).
#include "geometry/superquadric/fuzzy_part.h"
#include "query/structural/common_subgraph.h"

namespace fsdb {

struct CsgGraph;  // query/structural/csg_graph.h

struct CsgWeights {
  double components = 0.5, transforms = 0.2, structure = 0.3;  // documented defaults; sum normalised
};
struct CsgScore {
  double score = 0, components = 0, transforms = 0, structure = 0;
};

// structure  = matchedNodes / max(|query|, |stored|)                   (Bunke & Shearer; Shearer, Bunke, Venkatesh 2001)
// components = Σ matched leaf similarity / max(query leaves, stored leaves)
// transforms = Σ transformSimilarity(q, s) over matched leaf pairs / max(query leaves, stored leaves)
// score = (w1·components + w2·transforms + w3·structure) / (w1 + w2 + w3), in [0,1]; 1 only for an exact match.
// transformSimilarity is indexed like the leaf matrix: (query leaf, stored leaf).
CsgScore scoreCommonSubgraph(const CsgGraph& query, const CsgGraph& stored, const CommonSubgraph& match,
                             const LeafSimilarityMatrix& transformSimilarity, const CsgWeights& weights);

// S(A,B) of docs/api.md §5 on fuzzy parts: the 9 shape parameters (min over parameters of
// similarity(FuzzyNumber,FuzzyNumber), geometry/fuzzy/fuzzy_similarity.h), and on transforms (translate x/y/z,
// rotation, scale; documented above).
double partSimilarity(const FuzzyPart& a, const FuzzyPart& b);
double transformSimilarity(const FuzzyPart& a, const FuzzyPart& b);

}  // namespace fsdb
