#pragma once
// Linguistic search (docs/api.md §4 POST /query/linguistic, §5): the objects that satisfy a
// parsed query (query/linguistic/linguistic_query.h), best first.
//
// Contract:
// - Scores are V's: a part by scoreDescriptors on its descriptor values, a shape by scoreShape
//   on its components (the leaves of its resolved tree, references expanded). A result has a
//   score > 0, >= the request's threshold and >= the query's "at least"; results are in
//   descending score, equal scores by descending coverage (QueryScore::coverage: how much of
//   the sets the words say of the part its values span), then by ascending id; at most `limit`.
// - Indexed path (default): the candidates of the prefilter plan (query/linguistic/descriptor_prefilter.h)
//   run in the store's descriptor index, each with a bound >= its score from the supports the
//   index returns, and a bound >= its coverage (a said condition's crisp row: 0), are scored
//   best bounds first (ties by id), and scoring stops at the first candidate whose bounds cannot
//   beat the `limit`-th best score and coverage so far (nor reach the cut), so a
//   selective or top-heavy query reads the values of a few objects only. Level scan (parts,
//   when the plan is one descriptor condition or an "and" under a t-norm, driven by its first
//   descriptor child the words say of the part, else its first): the index rows are not all read first; the driver's ranges are cut into
//   pieces at the ends of its set's alpha-cuts (levelPieces, query/linguistic/descriptor_prefilter.h), read
//   best piece bound first, and a candidate is scored only once its bound beats every unread
//   piece's, so a broad query ("big": every part) reads the rows of its first levels only.
//   A crisp piece over which the set's membership is monotone is read best values first, a page
//   at a time; a flat one (a core: every row scores the same, ties go by id) is walked in id
//   order while that costs less than reading it whole, so a dense core yields its first
//   `limit` objects without reading the rest.
//   Scan path (`scan`):
//   every object of the kinds is scored. Both give the same results exactly (same ids,
//   scores, coverages, order): the plan only drops objects that score 0, and both score the same values
//   (a part's row holds describePart's exact values; pending objects are described from their
//   documents on both paths).
// - maxMillis > 0: a search still scoring after that long stops with limit_exceeded (413)
//   naming the limit.
// - A stored object whose document no longer parses (invalid_document: written around the API,
//   or by an older fsdb that accepted it) is skipped with a warning on the log, never the whole
//   search's answer; an object deleted meanwhile is skipped too.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "db/store.h"
#include "query/linguistic/linguistic_query.h"

namespace fsdb {

struct LinguisticSearchOptions {
  int limit = 10;
  double threshold = 0.0;
  std::vector<std::string> kinds = {"part", "shape"};
  bool scan = false;
  size_t maxNodes = 10000;  // for parsing stored shapes
  double maxMillis = 0;     // 0: no limit
  // The level scan's first read of a piece (rows by value, or ids of a walk; each next read
  // doubles): large enough that most pieces take one read; tests make it small to page often.
  int64_t firstLevelRead = 256;
};

struct LinguisticHit {
  int64_t id = 0;
  std::string kind, name;
  int version = 0;  // the version scored (a shape: its own; the parts it uses are their latest)
  QueryScore score;
};

struct LinguisticSearchResult {
  std::vector<LinguisticHit> hits;
  size_t candidates = 0;  // objects the prefilter kept (the level scan: the rows it read; the scan: all)
  size_t scored = 0;      // objects scored exactly
};

LinguisticSearchResult searchLinguistic(const Store& store, const LinguisticQuery& query,
                                        const LinguisticSearchOptions& options);

// The kinds a query searches: its subject ("any": parts and shapes) narrowed by `requestKind`
// ("" for no narrowing).
std::vector<std::string> searchKinds(const LinguisticQuery& query, const std::string& requestKind);

struct LinguisticRequestLimits {
  size_t maxNodes = 10000;
  double maxQueryMs = 0;
};

// The whole request {"text","limit","threshold","kind","scan"} -> {"parsed","results",
// "candidates","scored","scan","millis"}: validation (invalid_parameter / invalid_document naming the
// field), parsing with the active vocabulary (query/linguistic/vocabulary.h), search; "parsed" is
// toJson(query) of query/linguistic/linguistic_query.h. Shared by POST /query/linguistic and
// `fsdb query --db`. `relaxed`: how POST /query's partial matches rewrite the text's query
// when it found nothing (server/service/query_search.h).
struct QueryRelaxation {
  std::string aggregation;        // not empty: replaces the text's ("mean")
  std::optional<double> widenBy;  // set: closestMatchQuery(query, *widenBy) (query/linguistic/closest_match.h)
};
nlohmann::json linguisticQueryResponse(const Store& store, const nlohmann::json& request,
                                       const LinguisticRequestLimits& limits, const QueryRelaxation& relaxed = {});

}  // namespace fsdb
