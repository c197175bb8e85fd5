#pragma once
// One search box (docs/api.md §4 POST /query, §5): a query text goes to the search its parse calls
// for. A CSG formula, a text with an operation word or a text that only the CSG phrase grammar reads
// is structural (server/service/csg_search.h); every other text is linguistic
// (server/service/linguistic_search.h). The answer is that search's answer with "search":
// "linguistic" or "csg" added, so a client sees which one ran; the request's other members are
// that search's own (limit, threshold; kind and scan for linguistic, weights and prune for csg).
// Errors: a body without a string "text" is refused as the linguistic search refuses it (422 at
// "text"); everything else is the chosen search's (a text neither grammar reads gets the
// linguistic parser's 422 with its position and expected words).
#include <nlohmann/json.hpp>

#include "server/service/csg_search.h"
#include "server/service/linguistic_search.h"

namespace fsdb {

class Store;

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs);

}  // namespace fsdb
