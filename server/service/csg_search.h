#pragma once
// Structural search (Zhang, Pham & Chen, §5; docs/api.md §4 POST /query/csg, §5): the stored shapes
// whose CSG trees best match a query tree (query/structural/csg_query_text.h), best first.
//
// Contract:
// - Every live shape is a candidate (parts are not: a one-leaf query of a part is the linguistic
//   search's, POST /query/linguistic; a stored shape of one leaf is a one-leaf graph and is found).
// - The score of a shape is scoreCommonSubgraph (query/structural/csg_similarity.h) of largestCommonSubgraph
//   (query/structural/common_subgraph.h) between the query graph and the shape's graph (server/service/stored_graphs.h),
//   with leaf similarity: a description leaf of the query scores scoreDescriptors of its condition on
//   the stored leaf's descriptor values; a part leaf partSimilarity; transform similarity:
//   transformSimilarity for part leaves, 1 for descriptions (they say nothing of placement) and, for a
//   description with a spatial relation ("a sphere on top of a cylinder"), the relation's
//   membership on the match (query/structural/csg_relations.h; the bounds read it as 1).
// - Results have score > 0 and >= threshold, descending, ties by ascending id, at most `limit`.
// - Pruning (prune = true, the default) is exact: candidates go best signature bound first
//   (query/structural/csg_bound.h: node counts only), and the scan stops at the first whose bound cannot enter
//   the current top `limit` (below the limit-th score, or tied with it and a larger id, or below the
//   threshold); a candidate whose matrix bound (with its leaf similarities) cannot enter is skipped
//   without the subgraph search. So prune = false (every candidate matched) gives the same results,
//   ids, scores and order, as long as every match is complete (trees; a DAG search that hits
//   timeBudgetMs may find a different best-so-far mapping).
// - maxMillis > 0: a search still running after that long stops with limit_exceeded (413) naming it.
// - maxPairs: a candidate the scan reaches whose query leaves x stored leaves exceed it stops the
//   search with limit_exceeded (413) naming max_csg_pairs, before its similarity tables are
//   allocated (two doubles a pair). The per-search cache of leaf similarity columns is emptied
//   whenever it would hold more than maxPairs pairs, so memory stays within a few tables.
//   (A pruned search may stop before it reaches such a candidate and answer.)
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "db/store.h"
#include "query/structural/common_subgraph.h"
#include "query/structural/csg_query_text.h"
#include "query/structural/csg_relations.h"
#include "query/structural/csg_similarity.h"
#include "server/service/stored_graphs.h"

namespace fsdb {

struct CsgSearchOptions {
  CsgWeights weights;
  int limit = 10;
  double threshold = 0;
  double leafThreshold = 0;    // CommonSubgraphOptions::leafThreshold
  double timeBudgetMs = 100;   // per stored DAG (CommonSubgraphOptions::timeBudgetMs)
  bool prune = true;
  size_t maxNodes = 10000;     // for stored shapes
  double maxMillis = 0;        // 0: no limit
  size_t maxPairs = 4u << 20;  // query leaves x stored leaves of one match (--max-csg-pairs)
};

struct CsgHit {
  int64_t id = 0;
  CsgScore score;
  CommonSubgraph match;
  std::vector<RelationScore> relations;  // the query's spatial relations on this match (csg_relations.h)
  std::shared_ptr<const StoredGraph> stored;
};

struct CsgSearchResult {
  std::vector<CsgHit> hits;
  size_t candidates = 0;  // live shapes
  size_t bounded = 0;     // candidates whose leaf similarities were computed (signature bound passed)
  size_t matched = 0;     // candidates the common subgraph search ran on
};

CsgSearchResult searchCsg(const Store& store, const CsgQuery& query, const CsgSearchOptions& options,
                          StoredGraphCache& cache);

struct CsgRequestLimits {
  size_t maxNodes = 10000;  // query and stored graphs (--max-nodes)
  double maxQueryMs = 0;    // --max-query-ms (0: none); also the largest time_budget_ms
  size_t maxPairs = 4u << 20;  // --max-csg-pairs (CsgSearchOptions::maxPairs)
};

// The whole request {"text" | "tree", "weights":{"components","transforms","structure"}, "limit",
// "threshold", "leaf_threshold", "time_budget_ms", "prune"} -> {"parsed", "results":[{"id","name",
// "score","components","transforms","structure","complete","mapping":[{"query_node","query_path",
// "stored_node","stored_path","op","similarity"}], "relations" (texts with relations only):
// [{"text" (the relation's words), "subject", "object" (the two leaves' words), "query_path", "to",
// "stored_path", "stored_to" (null: unmatched), "checked" (both matched), "score"}]}], "candidates","bounded","matched","prune","millis"}.
// Validation names the field (invalid_document / invalid_parameter); texts are parsed with the
// active vocabulary and names resolved against the store. Shared by POST /query/csg and `fsdb query --db`.
nlohmann::json csgQueryResponse(const Store& store, const nlohmann::json& request, const CsgRequestLimits& limits,
                                StoredGraphCache& cache);

}  // namespace fsdb
