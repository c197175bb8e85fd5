// See server/service/query_search.h.
#include "server/service/query_search.h"

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_text.h"
#include "query/structural/unknown_words.h"

namespace fsdb {

namespace {

nlohmann::json searchText(const Store& store, const nlohmann::json& request, const std::string& text,
                          const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                          StoredGraphCache& graphs) {
  const bool csg = isCsgQueryText(text, activeVocabulary());
  nlohmann::json answer = csg ? csgQueryResponse(store, request, csgLimits, graphs)
                              : linguisticQueryResponse(store, request, linguisticLimits);
  answer["search"] = csg ? "csg" : "linguistic";
  return answer;
}

}  // namespace

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs) {
  // The same checks, codes and paths as the two searches' own.
  const std::string& text = requireString(requireField(requireObject(request, ""), "text", ""), "text");
  try {
    return searchText(store, request, text, linguisticLimits, csgLimits, graphs);
  } catch (const Error& refused) {
    if (refused.code() != errc::kInvalidParameter || refused.path() != "text") throw;
    // Words neither grammar knows: the text is read without them (query/structural/unknown_words.h).
    // When nothing is left, or what is left does not read either, the answer is the first refusal,
    // which names the first unknown word, its position and its closest words.
    KnownWordsReading reading;
    try {
      reading = readKnownWords(text, activeVocabulary());
    } catch (const Error&) {
      throw refused;
    }
    if (reading.unknown.empty() && reading.routed.empty()) throw refused;
    // The text without them first; when that does not read, their corrections chosen together.
    std::vector<std::string> tries;
    if (!reading.text.empty()) tries.push_back(reading.text);
    if (reading.corrected) tries.push_back(*reading.corrected);
    nlohmann::json answer;
    std::string searched;
    for (const std::string& attempt : tries) {
      nlohmann::json readable = request;
      readable["text"] = attempt;
      try {
        answer = searchText(store, readable, attempt, linguisticLimits, csgLimits, graphs);
        searched = attempt;
        break;
      } catch (const Error& again) {
        if (again.code() != errc::kInvalidParameter || again.path() != "text") throw;
      }
    }
    if (searched.empty() && reading.text.empty()) {
      // Nothing understood: the parser's closest words for the first word ("purple": are, cube,
      // curved) help less than saying which words are unknown, each with its plausible corrections.
      std::string message;
      for (size_t i = 0; i < reading.unknown.size() && i < 5; ++i) {
        const UnknownWord& u = reading.unknown[i];
        std::string closest;
        for (const std::string& c : u.closest) closest += (closest.empty() ? "" : ", ") + c;
        message += std::string(i ? "; " : "") + "unknown word '" + quotedWord(u.word) + "' at character " +
                   std::to_string(u.at) + (closest.empty() ? " (no known word is close)" : " (closest: " + closest + ")");
      }
      if (reading.unknown.size() > 5) message += "; and " + std::to_string(reading.unknown.size() - 5) + " more";
      throw Error(refused.code(), message + "; no word of the text is understood (GET /vocabulary lists the words)",
                  "text");
    }
    if (searched.empty()) throw refused;
    nlohmann::json ignored = nlohmann::json::array();
    for (const UnknownWord& u : reading.unknown)
      ignored.push_back({{"word", quotedWord(u.word)}, {"at", u.at}, {"did_you_mean", u.closest}});
    answer["ignored"] = std::move(ignored);
    // Routed words (query/linguistic/word_routes.h): what each became and why; the text is read
    // less surely through them, so every score is multiplied by their discounts.
    nlohmann::json routed = nlohmann::json::array();
    double discount = 1.0;
    for (const RoutedWord& r : reading.routed) {
      routed.push_back({{"word", quotedWord(r.route.word)}, {"at", r.at}, {"became", r.route.became},
                        {"why", r.route.why}, {"via", r.route.via}, {"discount", r.route.discount}});
      discount *= r.route.discount;
    }
    answer["routed"] = std::move(routed);
    if (discount < 1.0 && answer.contains("results") && answer["results"].is_array())
      for (nlohmann::json& result : answer["results"])
        if (result.contains("score") && result["score"].is_number())
          result["score"] = result["score"].get<double>() * discount;
    answer["read_text"] = searched;
    if (reading.corrected && *reading.corrected != searched) answer["did_you_mean"] = *reading.corrected;
    return answer;
  }
}

}  // namespace fsdb
