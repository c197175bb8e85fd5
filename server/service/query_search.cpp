// See server/service/query_search.h.
#include "server/service/query_search.h"

#include <algorithm>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "db/store.h"
#include "query/json/json_body.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_text.h"
#include "query/structural/unknown_words.h"

namespace fsdb {

namespace {

// The names a text may be ("snowman", "the dumbbell", "a round plate" for round-plate): its words
// after a request phrase, articles and fillers, joined by "-", " ", "_" and nothing.
std::vector<std::string> namesOfText(const std::string& text, const Vocabulary& vocabulary) {
  std::vector<query_tokens::Token> tokens;
  try {
    tokens = query_tokens::tokenize(text, 0, text.size());
  } catch (const Error&) {
    return {};
  }
  std::vector<std::string> words;
  for (const query_tokens::Token& t : tokens)
    if (t.text != "," && !vocabulary.isFiller(t.text)) words.push_back(t.text);
  size_t from = query_tokens::requestLength(
      [&](size_t k) { return k < words.size() ? &words[k] : nullptr; }, vocabulary);
  while (from < words.size() && std::find(queryArticles().begin(), queryArticles().end(), words[from]) != queryArticles().end())
    ++from;
  if (from >= words.size() || words.size() - from > 8) return {};
  std::vector<std::string> names;
  for (const char* joiner : {"-", " ", "_", ""}) {
    std::string name;
    for (size_t i = from; i < words.size(); ++i) name += (i > from ? joiner : "") + words[i];
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

// The stored parts and shapes (of the request's kind, when it names one) whose name the text is,
// as results that rank first: score 1, "named": true.
nlohmann::json objectsNamed(const Store& store, const nlohmann::json& request, const std::string& text) {
  nlohmann::json out = nlohmann::json::array();
  std::vector<std::string> kinds = {"part", "shape"};
  if (request.contains("kind") && request["kind"].is_string() &&
      (request["kind"] == "part" || request["kind"] == "shape"))
    kinds = {request["kind"].get<std::string>()};
  // One lookup for every spelling and kind (a query's only store read before its search).
  for (const StoredObject& o : store.named(namesOfText(text, activeVocabulary()), kinds))
    out.push_back({{"id", o.id}, {"kind", o.kind}, {"name", o.name}, {"version", o.version}, {"score", 1.0},
                   {"named", true}, {"explain", {{{"text", "the name '" + o.name + "'"}, {"score", 1.0}}}}});
  return out;
}

// The answer with the named objects first (each once) and its results after them, up to the
// request's limit (10 by default, as both searches).
void putNamedFirst(nlohmann::json* answer, const nlohmann::json& named, const nlohmann::json& request) {
  if (named.empty()) return;
  size_t limit = 10;
  if (request.contains("limit") && request["limit"].is_number_integer() && request["limit"].get<int64_t>() > 0)
    limit = static_cast<size_t>(request["limit"].get<int64_t>());
  nlohmann::json results = named;
  if (answer->contains("results") && (*answer)["results"].is_array())
    for (const nlohmann::json& r : (*answer)["results"]) {
      bool seen = false;
      for (const nlohmann::json& n : named) seen = seen || (n["id"] == r.value("id", nlohmann::json()));
      if (!seen) results.push_back(r);
    }
  if (results.size() > limit) results.erase(results.begin() + static_cast<std::ptrdiff_t>(limit), results.end());
  (*answer)["results"] = std::move(results);
}

nlohmann::json searchText(const Store& store, const nlohmann::json& request, const std::string& text,
                          const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                          StoredGraphCache& graphs) {
  const bool csg = isCsgQueryText(text, activeVocabulary());
  nlohmann::json answer = csg ? csgQueryResponse(store, request, csgLimits, graphs)
                              : linguisticQueryResponse(store, request, linguisticLimits);
  answer["search"] = csg ? "csg" : "linguistic";
  // No object meets every condition (min is 0 for all): the closest partial matches instead, by
  // the mean of the conditions' scores, each marked partial, its explain showing which failed.
  // Not for relations: their mean reads every pair of components of every shape (seconds on the
  // soak's catalogue), where the min's bounds prune.
  const nlohmann::json& parsed = answer.value("parsed", nlohmann::json::object());
  if (!csg && answer["results"].empty() && parsed.value("aggregation", "") == "min" &&
      parsed.value("condition", nlohmann::json::object()).value("kind", "") != "relation" &&
      parsed.value("at_least", 0.0) == 0.0 && !request.contains("threshold")) {
    nlohmann::json closest = linguisticQueryResponse(store, request, linguisticLimits, "mean");
    for (nlohmann::json& r : closest["results"]) r["partial"] = true;
    answer["results"] = std::move(closest["results"]);
    answer["partial"] = true;
  }
  return answer;
}

}  // namespace

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs) {
  // The same checks, codes and paths as the two searches' own.
  const std::string& text = requireString(requireField(requireObject(request, ""), "text", ""), "text");
  // A stored object's name ranks first ("snowman", "the dumbbell"), before whatever the words mean.
  const nlohmann::json named = objectsNamed(store, request, text);
  try {
    nlohmann::json answer = searchText(store, request, text, linguisticLimits, csgLimits, graphs);
    putNamedFirst(&answer, named, request);
    return answer;
  } catch (const Error& refused) {
    if (refused.code() != errc::kInvalidParameter || refused.path() != "text") throw;
    // Words no grammar reads that are a name: the named objects are the answer.
    if (!named.empty()) return {{"search", "name"}, {"results", named}};
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
    if (discount < 1.0 && answer.contains("results") && answer["results"].is_array()) {
      // The threshold (the request's, or the text's "at least") holds for the discounted scores:
      // the search kept every result at or above it before the discount, in the same order, so
      // dropping those that fall below it now is exact.
      double cut = request.value("threshold", 0.0);
      if (answer.contains("parsed") && answer["parsed"].is_object())
        cut = std::max(cut, answer["parsed"].value("at_least", 0.0));
      nlohmann::json kept = nlohmann::json::array();
      for (nlohmann::json& result : answer["results"]) {
        if (result.contains("score") && result["score"].is_number())
          result["score"] = result["score"].get<double>() * discount;
        if (result.value("score", 1.0) >= cut) kept.push_back(std::move(result));
      }
      answer["results"] = std::move(kept);
    }
    answer["read_text"] = searched;
    if (reading.corrected && *reading.corrected != searched) answer["did_you_mean"] = *reading.corrected;
    return answer;
  }
}

}  // namespace fsdb
