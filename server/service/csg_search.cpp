// See server/service/csg_search.h.
#include "server/service/csg_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "geometry/core/error.h"
#include "query/structural/csg_bound.h"
#include "query/structural/csg_query_print.h"
#include "query/structural/csg_relations.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/documents.h"

namespace fsdb {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kDefaultLimit = 10;
constexpr int kMaxLimit = 1000;
constexpr double kDefaultTimeBudgetMs = 100;
constexpr double kMaxTimeBudgetMs = 10000;

double millisSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Best first, ties by id.
bool better(const CsgHit& a, const CsgHit& b) {
  return a.score.score != b.score.score ? a.score.score > b.score.score : a.id < b.id;
}

struct Candidate {
  double bound;
  std::shared_ptr<const StoredGraph> graph;
};

class Search {
 public:
  Search(const CsgQuery& query, const CsgSearchOptions& options)
      : query_(query), options_(options), signature_(csgSignature(query.graph)),
        limit_(static_cast<size_t>(std::max(1, options.limit))), start_(Clock::now()) {
    // Described leaves score as the linguistic search does: over the descriptors' degree domains
    // (stored degrees are clamped into them).
    for (const CsgQueryLeaf& ql : query_.leaves)
      leafConditions_.push_back(ql.condition ? std::optional<LinguisticQuery>(withinDegreeDomains(*ql.condition))
                                             : std::nullopt);
  }

  CsgSearchResult run(const Store& store, StoredGraphCache& cache) {
    const std::shared_ptr<const StoreVersions> current = cache.versions(store);
    const StoreVersions& versions = *current;
    std::vector<Candidate> candidates;
    // Missing graphs (the first search of a process, or after writes) are built in parallel.
    for (std::shared_ptr<const StoredGraph>& g :
         cache.graphs(store, versions, options_.maxNodes, [this]() { checkTime(); })) {
      if (!g) continue;  // deleted meanwhile
      const double bound = signatureBound(signature_, g->signature, options_.weights);
      candidates.push_back({bound, std::move(g)});
    }
    result_.candidates = candidates.size();
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.bound != b.bound ? a.bound > b.bound : a.graph->id < b.graph->id;
    });
    for (const Candidate& c : candidates) {
      checkTime();
      if (options_.prune && !canEnter(c.bound, c.graph->id)) break;  // sorted: no later one can either
      match(c.graph);
    }
    return std::move(result_);
  }

 private:
  void match(const std::shared_ptr<const StoredGraph>& handle) {
    const StoredGraph& stored = *handle;
    ++result_.bounded;
    const int rows = query_.graph.leafCount, cols = stored.shape.graph.leafCount;
    const size_t pairs = size_t(rows) * size_t(cols);
    if (pairs > options_.maxPairs)
      throw Error(errc::kLimitExceeded,
                  std::to_string(rows) + " query leaves x " + std::to_string(cols) + " leaves of stored shape " +
                      std::to_string(stored.id) + " exceed max_csg_pairs=" + std::to_string(options_.maxPairs) +
                      "; query fewer leaves or raise --max-csg-pairs",
                  "text");
    // Each cached column holds `rows` pairs; this shape may add `cols` columns.
    if ((memo_.size() + size_t(cols)) * size_t(rows) > options_.maxPairs) memo_.clear();
    LeafSimilarityMatrix leaf{rows, cols, std::vector<double>(size_t(rows) * size_t(cols))};
    LeafSimilarityMatrix transform{rows, cols, std::vector<double>(size_t(rows) * size_t(cols))};
    for (int s = 0; s < cols; ++s) {
      const LeafColumn& c = column(stored, s);
      for (int q = 0; q < rows; ++q) {
        leaf.values[size_t(q) * cols + s] = c.leaf[size_t(q)];
        transform.values[size_t(q) * cols + s] = c.transform[size_t(q)];
      }
    }
    if (options_.prune && !canEnter(matrixBound(signature_, stored.signature, leaf, transform, options_.leafThreshold,
                                                options_.weights),
                                    stored.id))
      return;
    ++result_.matched;
    CsgHit hit;
    hit.id = stored.id;
    hit.match = largestCommonSubgraph(query_.graph, stored.shape.graph, leaf,
                                      {options_.leafThreshold, options_.timeBudgetMs},
                                      [this] { checkTime(); });  // max_query_ms holds inside one long match too
    hit.relations = scoreRelations(query_, stored.shape, leaf, hit.match, transform);  // may improve the mapping
    hit.score = scoreCommonSubgraph(query_.graph, stored.shape.graph, hit.match, transform, options_.weights);
    if (!(hit.score.score > 0) || hit.score.score < options_.threshold) return;
    hit.stored = handle;
    auto& hits = result_.hits;
    hits.insert(std::upper_bound(hits.begin(), hits.end(), hit, better), std::move(hit));
    if (hits.size() > limit_) hits.pop_back();
  }

  // The similarities of every query leaf to stored leaf s, computed once per distinct part in a
  // search (trees share stored parts, and parts from the same words are equal: the cache gives
  // them one id, StoredGraph::leafParts).
  struct LeafColumn {
    std::vector<double> leaf, transform;
  };
  const LeafColumn& column(const StoredGraph& stored, int s) {
    const FuzzyPart& sp = stored.shape.leaves[size_t(s)].part;
    const auto found = memo_.find(stored.leafParts[size_t(s)]);
    if (found != memo_.end()) return found->second;
    LeafColumn c;
    for (size_t q = 0; q < query_.leaves.size(); ++q) {
      const CsgQueryLeaf& ql = query_.leaves[q];
      const std::optional<LinguisticQuery>& condition = leafConditions_[q];
      c.leaf.push_back(condition ? scoreDescriptors(*condition, stored.leafDescriptors[size_t(s)]).score
                                 : partSimilarity(ql.part, sp));
      c.transform.push_back(condition ? 1.0 : transformSimilarity(ql.part, sp));
    }
    return memo_.emplace(stored.leafParts[size_t(s)], std::move(c)).first->second;
  }

  // Whether a candidate with this score bound could still be among the results.
  bool canEnter(double bound, int64_t id) const {
    if (bound < options_.threshold || !(bound > kBoundSlack)) return false;
    const auto& hits = result_.hits;
    if (hits.size() < limit_) return true;
    const CsgHit& kth = hits.back();
    return bound > kth.score.score || (bound == kth.score.score && id < kth.id);
  }

  void checkTime() const {
    if (options_.maxMillis > 0 && millisSince(start_) > options_.maxMillis)
      throw Error(errc::kLimitExceeded,
                  "the CSG query ran longer than max_query_ms=" +
                      std::to_string(static_cast<long long>(options_.maxMillis)) +
                      " ms; raise threshold, lower time_budget_ms, or raise --max-query-ms",
                  "text");
  }

  const CsgQuery& query_;
  std::vector<std::optional<LinguisticQuery>> leafConditions_;  // the leaves' conditions, withinDegreeDomains
  const CsgSearchOptions& options_;
  const CsgSignature signature_;
  const size_t limit_;
  const Clock::time_point start_;
  CsgSearchResult result_;
  std::unordered_map<int64_t, LeafColumn> memo_;  // by StoredGraph::leafParts id
};

nlohmann::json mappingJson(const CsgQuery& query, const CsgHit& hit) {
  nlohmann::json out = nlohmann::json::array();
  const CsgGraph& stored = hit.stored->shape.graph;
  for (const NodeMatch& m : hit.match.matches)
    out.push_back({{"query_node", m.queryNode},
                   {"query_path", query.graph.nodes[size_t(m.queryNode)].path},
                   {"stored_node", m.storedNode},
                   {"stored_path", stored.nodes[size_t(m.storedNode)].path},
                   {"op", csgGraphOpName(stored.nodes[size_t(m.storedNode)].op)},
                   {"similarity", m.similarity}});
  return out;
}

// Each relation of the query on this hit: its words, the stored leaves it was checked on, its membership.
nlohmann::json relationsJson(const CsgQuery& query, const CsgHit& hit) {
  const std::vector<std::string> storedPaths = hit.stored->shape.graph.leafPaths(), queryPaths = query.graph.leafPaths();
  const auto storedPath = [&](int leaf) { return leaf < 0 ? nlohmann::json(nullptr) : nlohmann::json(storedPaths[size_t(leaf)]); };
  nlohmann::json out = nlohmann::json::array();
  for (const RelationScore& r : hit.relations) {
    const CsgQueryLeaf& leaf = query.leaves[size_t(r.queryLeaf)];
    out.push_back({{"text", leaf.relation->text},
                   {"subject", leaf.text},
                   {"object", query.leaves[leaf.relation->to].text},
                   {"query_path", queryPaths[size_t(r.queryLeaf)]},
                   {"to", queryPaths[leaf.relation->to]},
                   {"stored_path", storedPath(r.storedLeaf)},
                   {"stored_to", storedPath(r.storedReference)},
                   {"checked", r.checked},
                   {"score", r.score}});
  }
  return out;
}

CsgWeights parseWeights(const nlohmann::json& request) {
  CsgWeights w;
  if (!request.contains("weights")) return w;
  const nlohmann::json& j = requireObject(request["weights"], "weights");
  rejectUnknownKeys(j, "weights", {"components", "transforms", "structure"});
  const double big = 1e6;
  w.components = optionalNumberIn(j, "weights", "components", w.components, 0, big);
  w.transforms = optionalNumberIn(j, "weights", "transforms", w.transforms, 0, big);
  w.structure = optionalNumberIn(j, "weights", "structure", w.structure, 0, big);
  if (!(w.components + w.transforms + w.structure > 0))
    throw Error(errc::kInvalidParameter, "weights must not all be 0", "weights");
  return w;
}

}  // namespace

CsgSearchResult searchCsg(const Store& store, const CsgQuery& query, const CsgSearchOptions& options,
                          StoredGraphCache& cache) {
  return Search(query, options).run(store, cache);
}

nlohmann::json csgQueryResponse(const Store& store, const nlohmann::json& request, const CsgRequestLimits& limits,
                                StoredGraphCache& cache) {
  const auto start = Clock::now();
  requireObject(request, "");
  rejectUnknownKeys(request, "",
                    {"text", "tree", "weights", "limit", "threshold", "leaf_threshold", "time_budget_ms", "prune"});
  if (request.contains("text") == request.contains("tree"))
    throw Error(errc::kInvalidDocument, "give exactly one of \"text\" and \"tree\"",
                request.contains("text") ? "tree" : "text");
  CsgSearchOptions options;
  options.weights = parseWeights(request);
  options.limit = static_cast<int>(optionalInteger(request, "", "limit", kDefaultLimit, 1, kMaxLimit));
  options.threshold = optionalNumberIn(request, "", "threshold", 0.0, 0.0, 1.0);
  options.leafThreshold = optionalNumberIn(request, "", "leaf_threshold", 0.0, 0.0, 1.0);
  const double maxBudget = limits.maxQueryMs > 0 ? std::min(kMaxTimeBudgetMs, limits.maxQueryMs) : kMaxTimeBudgetMs;
  options.timeBudgetMs = optionalNumberIn(request, "", "time_budget_ms", std::min(kDefaultTimeBudgetMs, maxBudget), 0,
                                          maxBudget);
  options.prune = optionalBoolean(request, "", "prune", true);
  options.maxNodes = limits.maxNodes;
  options.maxMillis = limits.maxQueryMs;
  options.maxPairs = limits.maxPairs;
  const ReferenceResolver resolver = storeResolver(store);
  const CsgQuery query =
      request.contains("text")
          ? parseCsgQuery(requireString(request["text"], "text"), activeVocabulary(), resolver, limits.maxNodes)
          : csgQueryFromDocument(request["tree"], limits.maxNodes, resolver);
  const CsgSearchResult found = searchCsg(store, query, options, cache);
  nlohmann::json results = nlohmann::json::array();
  const bool relations = hasRelations(query);
  for (const CsgHit& hit : found.hits) {
    results.push_back({{"id", hit.id},
                       {"name", hit.stored->name},
                       {"score", hit.score.score},
                       {"components", hit.score.components},
                       {"transforms", hit.score.transforms},
                       {"structure", hit.score.structure},
                       {"complete", hit.match.complete},
                       {"mapping", mappingJson(query, hit)}});
    if (relations) results.back()["relations"] = relationsJson(query, hit);
  }
  nlohmann::json parsed = toJson(query);
  // How a text was read, in the phrase form's own words (query/structural/csg_query_print.h);
  // stored parts of a formula have no phrase (the formula names them).
  if (request.contains("text")) {
    try {
      parsed["read_as"] = csgQueryText(query, activeVocabulary());
    } catch (const Error&) {
    }
  }
  return {{"parsed", std::move(parsed)},  {"results", results},      {"candidates", found.candidates},
          {"bounded", found.bounded}, {"matched", found.matched}, {"prune", options.prune},
          {"millis", millisSince(start)}};
}

}  // namespace fsdb
