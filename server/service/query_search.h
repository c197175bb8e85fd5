#pragma once
// One search box (docs/api.md §4 POST /query, §5): a query text goes to the search its parse calls
// for. A CSG formula, a text with an operation word or a text that only the CSG phrase grammar reads
// is structural (server/service/csg_search.h); every other text is linguistic
// (server/service/linguistic_search.h). The answer is that search's answer with "search":
// "linguistic" or "csg" added, so a client sees which one ran; the request's other members are
// that search's own (limit, threshold; kind and scan for linguistic, weights and prune for csg).
// Unknown words are no dead end: when neither grammar reads the text, it is searched without the
// words neither knows (query/structural/unknown_words.h), or, when that does not read, with their
// corrections chosen together; the answer adds "ignored" ([{"word", "at", "did_you_mean": [closest
// words]}]), "read_text" (the text searched) and, when the search ran without corrections that
// exist, "did_you_mean" (the whole corrected text).
// Names: a text that is a stored part's or shape's name (after a request phrase and articles;
// words joined by "-", " ", "_" or nothing) puts that object first (score 1, "named": true); a
// text no grammar reads but that is a name is answered {"search": "name", "results": [...]}. In
// a linguistic text without a relation, a name its words hold in another order scores 1, and a
// name among more words comes first of the results with its score (docs/api.md).
// Partial matches: a linguistic text without a relation that no object meets at all (every score
// 0 under min, no threshold) is searched again by the mean of its conditions (the text's own
// "using ..." too gives way); the answer and its results carry "partial": true. When that finds
// nothing either, or the text has a relation, its closest matches (query/linguistic/closest_match.h:
// conditions widened step by step, placements ignored; scores halved; explain with "closeness")
// are the answer, marked partial, with "closest": {"widened_by", "placement_ignored"}.
// Errors: a body without a string "text" is refused as the linguistic search refuses it (422 at
// "text"); everything else is the chosen search's. A text that does not read even without its
// unknown words (or has nothing else) gets the first refusal: the linguistic parser's 422 with the
// position and the expected or closest words.
#include <nlohmann/json.hpp>

#include "server/service/csg_search.h"
#include "server/service/linguistic_search.h"

namespace fsdb {

class Store;

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs);

}  // namespace fsdb
