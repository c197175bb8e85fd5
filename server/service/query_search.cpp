// See server/service/query_search.h.
#include "server/service/query_search.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "db/store.h"
#include "query/json/json_body.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"
#include "query/linguistic/wordnet.h"
#include "query/structural/csg_query_text.h"
#include "query/structural/unknown_words.h"
#include "server/service/documents.h"
#include "server/service/typical_first.h"

namespace fsdb {

namespace {

// The words of a text after a request phrase and its leading articles, without fillers and
// commas ("find the small snowman, please" -> small, snowman); empty when it does not tokenise.
std::vector<std::string> wordsOfText(const std::string& text, const Vocabulary& vocabulary) {
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
  return std::vector<std::string>(words.begin() + static_cast<std::ptrdiff_t>(from), words.end());
}

// The names a text may be ("snowman", "the dumbbell", "a round plate" for round-plate): its words
// joined by "-", " ", "_" and nothing; none longer than a stored name may be (kMaxNameLength).
std::vector<std::string> namesOfText(const std::vector<std::string>& words) {
  if (words.empty() || words.size() > 8) return {};
  size_t letters = 0;
  for (const std::string& w : words) letters += w.size();
  if (letters > kMaxNameLength) return {};
  std::vector<std::string> names;
  for (const char* joiner : {"-", " ", "_", ""}) {
    std::string name;
    for (size_t i = 0; i < words.size(); ++i) name += (i ? joiner : "") + words[i];
    if (name.size() <= kMaxNameLength && std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(name);
  }
  return names;
}

// The kinds a request searches by name and words: its `kind` when that is part or shape.
std::vector<std::string> requestKinds(const nlohmann::json& request) {
  if (request.contains("kind") && request["kind"].is_string() &&
      (request["kind"] == "part" || request["kind"] == "shape"))
    return {request["kind"].get<std::string>()};
  return {"part", "shape"};
}

// How an object's own words score when they hold every word of the text. They answer only where
// the meaning found nothing whole (no result, partial matches, or a text no grammar reads), so
// the score ranks them among partial matches: above those that fail half their conditions.
constexpr double kDescribedScore = 0.5;

// The stored parts and shapes whose own words (name, meta.description, descriptors) hold every
// content word of the text, as results: score kDescribedScore, "described": true. Not for texts
// with "not" (a word search cannot say what an object is not).
nlohmann::json objectsDescribed(const Store& store, const nlohmann::json& request, const std::vector<std::string>& words,
                                size_t limit) {
  std::vector<std::string> content;
  for (const std::string& w : words) {
    if (w == "not" || w == "no" || w == "without") return nlohmann::json::array();
    if (!query_tokens::functionWord(w) && std::isalnum(static_cast<unsigned char>(w[0])))
      content.push_back(w);
  }
  nlohmann::json out = nlohmann::json::array();
  if (content.empty() || content.size() > Store::kMaxTextWords) return out;
  for (const StoredObject& o : store.described(content, requestKinds(request), static_cast<int>(limit)))
    out.push_back({{"id", o.id}, {"kind", o.kind}, {"name", o.name}, {"version", o.version}, {"score", kDescribedScore},
                   {"described", true}, {"explain", {{{"text", "its own words"}, {"score", kDescribedScore}}}}});
  return out;
}

// Texts of which no word is understood are searched in objects' own words one word at a time:
// at most this many content words (each is one full-text lookup).
constexpr size_t kMostPartlyDescribedWords = 8;

// Whether WordNet has `word` as a noun of the same synset, in its first four senses, as one of the
// vocabulary's nouns without a geometry ("form" and "shape", "piece" and "part"): a word any
// description may hold.
bool genericNoun(const std::string& word) {
  const WordNet* wordnet = systemWordNet();
  if (!wordnet) return false;
  constexpr size_t kSenses = 4;
  const Vocabulary& v = activeVocabulary();
  for (const std::string& base : wordnet->baseForms(word, WordNet::Pos::kNoun)) {
    const std::vector<WordNet::Synset> senses = wordnet->senses(base, WordNet::Pos::kNoun);
    for (size_t i = 0; i < senses.size() && i < kSenses; ++i)
      for (const std::string& w : senses[i].words) {
        const Noun* n = v.noun(w);
        if (n && n->params.is_null()) return true;
      }
  }
  return false;
}

// The stored parts and shapes whose own words hold some of the words no grammar reads of a text
// that does not read (objectsDescribed asks for every content word): "a silk ribbon" finds the
// object described as a ribbon. The grammars' own words are left out ("top" or "end", in many
// descriptions, would list anything for "a spinning top"), and so are generic nouns ("form").
// Scored kDescribedScore times the share of those words held, most held first (then by id),
// "described" and "partial": true; explain says which words. `held`: the words some result holds.
nlohmann::json objectsPartlyDescribed(const Store& store, const nlohmann::json& request,
                                      const std::vector<std::string>& words, size_t limit,
                                      std::unordered_set<std::string>* held) {
  std::vector<std::string> content;
  for (const std::string& w : words) {
    if (w == "not" || w == "no" || w == "without") return nlohmann::json::array();
    if (!query_tokens::functionWord(w) && std::isalnum(static_cast<unsigned char>(w[0])) &&
        std::find(content.begin(), content.end(), w) == content.end() && !knowsLinguisticWord(w, activeVocabulary()) &&
        !genericNoun(w)) {
      content.push_back(w);
      if (content.size() > kMostPartlyDescribedWords) return nlohmann::json::array();  // not a few words
    }
  }
  if (content.empty()) return nlohmann::json::array();
  struct Held {
    StoredObject object;
    std::vector<std::string> words;
  };
  std::map<std::pair<std::string, int64_t>, Held> objects;
  for (const std::string& w : content)
    for (const StoredObject& o : store.described({w}, requestKinds(request), static_cast<int>(limit))) {
      Held& h = objects[{o.kind, o.id}];
      if (h.words.empty()) h.object = o;
      h.words.push_back(w);
    }
  std::vector<const Held*> ranked;
  for (const auto& [key, h] : objects) ranked.push_back(&h);
  std::stable_sort(ranked.begin(), ranked.end(), [](const Held* a, const Held* b) {
    return a->words.size() != b->words.size() ? a->words.size() > b->words.size() : a->object.id < b->object.id;
  });
  nlohmann::json out = nlohmann::json::array();
  for (const Held* h : ranked) {
    if (out.size() >= limit) break;
    held->insert(h->words.begin(), h->words.end());
    const double score = kDescribedScore * static_cast<double>(h->words.size()) / static_cast<double>(content.size());
    std::string said;
    for (const std::string& w : h->words) said += (said.empty() ? "'" : ", '") + w + "'";
    const std::string text = "its own words hold " + said + " (" + std::to_string(h->words.size()) + " of " +
                             std::to_string(content.size()) + " words)";
    out.push_back({{"id", h->object.id}, {"kind", h->object.kind}, {"name", h->object.name},
                   {"version", h->object.version}, {"score", score}, {"described", true}, {"partial", true},
                   {"explain", {{{"text", text}, {"score", score}}}}});
  }
  return out;
}

// The stored parts and shapes (of the request's kind, when it names one) whose name the text is,
// as results that rank first: score 1, "named": true.
nlohmann::json objectsNamed(const Store& store, const nlohmann::json& request, const std::vector<std::string>& words) {
  nlohmann::json out = nlohmann::json::array();
  // One lookup for every spelling and kind.
  for (const StoredObject& o : store.named(namesOfText(words), requestKinds(request)))
    out.push_back({{"id", o.id}, {"kind", o.kind}, {"name", o.name}, {"version", o.version}, {"score", 1.0},
                   {"named", true}, {"explain", {{{"text", "the name '" + o.name + "'"}, {"score", 1.0}}}}});
  return out;
}

// Texts longer than this are not searched for names they nearly hold (nearNames): at most about
// 50 words, so at most a few hundred spellings to look up.
constexpr size_t kLongestNearlyNamedText = 300;

// The names a text that no grammar reads as it is nearly holds: each run of up to four
// consecutive words the grammars lack (unknown or only routed: "egg form" gives egg, form and
// egg-form, "a mushroom form" mushroom), joined as namesOfText joins them; and, for the first
// three unknown words (no route either) of four to twenty letters that WordNet does not know
// (dictionaryBaseForms: "wall" is meant as it is, no misspelt ball; of a word it knows, only its base
// forms one edit away: "spikes" gives spike), every spelling one edit away
// (a letter left out, added, changed, or two swapped: "snowmn" gives snowman, "tabel" table).
// Each name once, runs first.
//
// `related`, when given: for the same unknown words, the names WordNet relates to them as nouns
// (wordNetNames): "a pillow" may be the object named cushion.
void wordNetNames(const std::string& word, std::vector<std::string>* synonyms, std::vector<std::string>* hypernyms);
void nearNames(const std::string& text, const KnownWordsReading& reading, std::vector<std::string>* runs,
               std::vector<std::string>* edits, std::vector<std::string>* synonyms = nullptr,
               std::vector<std::string>* hypernyms = nullptr) {
  // A name is a few words: long texts are not names, and each spelling costs a lookup.
  if (text.size() > kLongestNearlyNamedText) return;
  std::vector<query_tokens::Token> tokens;
  try {
    tokens = query_tokens::tokenize(text, 0, text.size());
  } catch (const Error&) {
    return;
  }
  std::vector<size_t> lacking;  // offsets of the words the grammars lack
  for (const UnknownWord& u : reading.unknown) lacking.push_back(u.at);
  for (const RoutedWord& r : reading.routed) lacking.push_back(r.at);
  const auto lacks = [&](const query_tokens::Token& t) {
    return std::find(lacking.begin(), lacking.end(), t.offset) != lacking.end();
  };
  std::unordered_set<std::string> listed;  // each name once (a word's spellings repeat)
  const auto list = [&](std::vector<std::string>* names, std::string name) {
    if (listed.insert(name).second) names->push_back(std::move(name));
  };
  std::vector<std::string> words;
  for (size_t i = 0; i <= tokens.size(); ++i) {
    if (i < tokens.size() && lacks(tokens[i])) {
      words.push_back(tokens[i].text);
      continue;
    }
    for (size_t from = 0; from < words.size(); ++from)
      for (size_t n = 1; n <= 4 && from + n <= words.size(); ++n)
        for (std::string& name : namesOfText({words.begin() + static_cast<std::ptrdiff_t>(from),
                                              words.begin() + static_cast<std::ptrdiff_t>(from + n)}))
          list(runs, std::move(name));
    words.clear();
  }
  static const std::string kLetters = "abcdefghijklmnopqrstuvwxyz-";
  size_t edited = 0;
  for (const UnknownWord& u : reading.unknown) {
    const std::string& w = u.word;
    if (edited == 3) break;
    if (w.size() < 4 || w.size() > 20) continue;
    ++edited;
    if (synonyms && hypernyms) {
      std::vector<std::string> same, broader;
      wordNetNames(w, &same, &broader);
      for (std::string& name : same) list(synonyms, std::move(name));
      for (std::string& name : broader) list(hypernyms, std::move(name));
    }
    std::vector<std::string> near;
    for (size_t k = 0; k < w.size(); ++k) near.push_back(w.substr(0, k) + w.substr(k + 1));
    for (size_t k = 0; k + 1 < w.size(); ++k) {
      std::string swapped = w;
      std::swap(swapped[k], swapped[k + 1]);
      near.push_back(std::move(swapped));
    }
    for (size_t k = 0; k <= w.size(); ++k)
      for (const char c : kLetters) {
        near.push_back(w.substr(0, k) + c + w.substr(k));
        if (k < w.size() && c != w[k]) near.push_back(w.substr(0, k) + c + w.substr(k + 1));
      }
    // A word of the dictionary was meant as it is: of its spellings, only its own base forms
    // ("spikes": spike, "snowmen": snowman) name objects; "wall" is no misspelt ball.
    const std::vector<std::string> bases = dictionaryBaseForms(w);
    const bool meant = !bases.empty();
    for (std::string& name : near)
      if (name != w && (!meant || std::find(bases.begin(), bases.end(), name) != bases.end()))
        list(edits, std::move(name));
  }
}

// How names a text nearly holds score (nearNames): below an exact name (1) and above the
// objects' own words (kDescribedScore); a name in the text's words above a spelling one edit away,
// which a name WordNet gives as a synonym of an unknown word matches, and a hypernym's is that
// times WordNet routes' hypernym discount (0.9, word_routes.h).
constexpr double kNameInTextScore = 0.9;
constexpr double kNearNameScore = 0.8;
constexpr double kHypernymNameScore = 0.9 * kNearNameScore;

// The nouns WordNet gives for an unknown word, as names: the words of its first four senses as a
// noun (synonyms: "sofa" for couch) and of their hypernyms ("cushion" for pillow), each as the
// spellings namesOfText makes of its words. The word itself is not among them. Not their
// hyponyms, the word's kinds (tried: "a jewel" found the object named diamond, but "a plus sign"
// found beam, a kind of sign, and "board of wood" log, a kind of wood).
void wordNetNames(const std::string& word, std::vector<std::string>* synonyms, std::vector<std::string>* hypernyms) {
  const WordNet* wordnet = systemWordNet();
  if (!wordnet) return;
  const auto add = [&](const std::string& phrase, std::vector<std::string>* out) {
    if (phrase == word) return;
    std::vector<std::string> words;
    size_t from = 0;
    while (from < phrase.size()) {
      size_t to = phrase.find(' ', from);
      if (to == std::string::npos) to = phrase.size();
      if (to > from) words.push_back(phrase.substr(from, to - from));
      from = to + 1;
    }
    if (words.empty() || words.size() > 3) return;
    for (std::string& name : namesOfText(words)) out->push_back(std::move(name));
  };
  for (const std::string& base : wordnet->baseForms(word, WordNet::Pos::kNoun)) {
    const std::vector<WordNet::Synset> senses = wordnet->senses(base, WordNet::Pos::kNoun);
    for (size_t k = 0; k < senses.size() && k < 4; ++k) {
      for (const std::string& w : senses[k].words) add(w, synonyms);
      for (const WordNet::Pointer& p : senses[k].pointers)
        if (p.symbol == "@" && p.pos == WordNet::Pos::kNoun)
          for (const std::string& w : wordnet->synsetAt(WordNet::Pos::kNoun, p.offset).words) add(w, hypernyms);
    }
  }
}

// The stored parts and shapes whose name the text nearly holds (nearNames), as named results:
// the names in its words (kNameInTextScore), then those one edit away (kNearNameScore), each
// object once, looked up kMaxNamedLookups names a statement.
nlohmann::json objectsNearlyNamed(const Store& store, const nlohmann::json& request, const std::string& text,
                                  const KnownWordsReading& reading) {
  std::vector<std::string> runs, edits, synonyms, hypernyms;
  nearNames(text, reading, &runs, &edits, &synonyms, &hypernyms);
  nlohmann::json out = nlohmann::json::array();
  std::unordered_set<int64_t> seen;
  const std::vector<std::string> kinds = requestKinds(request);
  // The names in the words, then WordNet's synonyms of an unknown word, spellings one edit away,
  // WordNet's hypernyms.
  enum class How { kRun, kSynonym, kTypo, kHypernym };
  for (const How how : {How::kRun, How::kSynonym, How::kTypo, How::kHypernym}) {
    const std::vector<std::string>& names = how == How::kRun       ? runs
                                            : how == How::kSynonym ? synonyms
                                            : how == How::kTypo    ? edits
                                                                   : hypernyms;
    for (size_t at = 0; at < names.size(); at += Store::kMaxNamedLookups) {
      const std::vector<std::string> chunk(
          names.begin() + static_cast<std::ptrdiff_t>(at),
          names.begin() + static_cast<std::ptrdiff_t>(std::min(names.size(), at + Store::kMaxNamedLookups)));
      for (const StoredObject& o : store.named(chunk, kinds)) {
        if (!seen.insert(o.id).second) continue;
        const double score = how == How::kRun        ? kNameInTextScore
                             : how == How::kHypernym ? kHypernymNameScore
                                                     : kNearNameScore;
        const std::string why =
            how == How::kRun       ? "the name '" + o.name + "' among the words of the text"
            : how == How::kTypo    ? "the name '" + o.name + "', one letter away from a word of the text"
            : how == How::kSynonym ? "the name '" + o.name + "', a WordNet synonym of a word of the text"
                                   : "the name '" + o.name + "', a WordNet hypernym of a word of the text";
        out.push_back({{"id", o.id}, {"kind", o.kind}, {"name", o.name}, {"version", o.version}, {"score", score},
                       {"named", true}, {"explain", {{{"text", why}, {"score", score}}}}});
      }
    }
  }
  return out;
}

// The content words of a text's words: not function words, not numbers.
std::vector<std::string> contentWordsOf(const std::vector<std::string>& words) {
  std::vector<std::string> content;
  for (const std::string& w : words)
    if (!query_tokens::functionWord(w) && std::isalpha(static_cast<unsigned char>(w[0]))) content.push_back(w);
  return content;
}

// Texts with more content words than this are not looked up for their words' names in another
// order: four give 24 orders, 96 spellings, one statement with the single words'.
constexpr size_t kMostWordsReordered = 4;

// The stored objects whose name is one content word of the text (or its singular: "spheres" gives
// sphere) or a synonym of one of its nouns (nounSynonymsOf), or all its words in any order ("rod bent slightly" for slightly-bent-rod, "ball small" for
// small-ball; texts of two to kMostWordsReordered content words), each joined as namesOfText joins
// them: one lookup of at most Store::kMaxNamedLookups spellings. A text of more distinct words
// than that looks up none: a name is a few words, and a long text's words name many things by
// chance. The second of each pair: whether the name is the whole text reordered.
std::vector<std::pair<StoredObject, bool>> objectsNamedByWords(const Store& store, const nlohmann::json& request,
                                                               std::vector<std::string> content,
                                                               const std::vector<std::string>& synonyms) {
  std::vector<std::string> names;
  std::unordered_set<std::string> listed;
  const auto list = [&](std::string name) {
    if (name.size() <= kMaxNameLength && listed.insert(name).second) names.push_back(std::move(name));
  };
  for (const std::string& w : content) {
    list(w);
    if (w.size() > 3 && w.back() == 's' && w[w.size() - 2] != 's') list(w.substr(0, w.size() - 1));
  }
  for (const std::string& w : synonyms) list(w);
  if (names.size() > Store::kMaxNamedLookups) return {};
  const size_t singles = names.size();
  if (content.size() >= 2 && content.size() <= kMostWordsReordered) {
    std::sort(content.begin(), content.end());
    do {
      for (std::string& name : namesOfText(content)) list(std::move(name));
    } while (std::next_permutation(content.begin(), content.end()) && names.size() < Store::kMaxNamedLookups);
  }
  if (names.size() > Store::kMaxNamedLookups) names.resize(Store::kMaxNamedLookups);
  if (names.empty()) return {};
  const std::unordered_set<std::string> single(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(singles));
  std::vector<std::pair<StoredObject, bool>> out;
  for (StoredObject& o : store.named(names, requestKinds(request))) {
    const bool whole = content.size() >= 2 && !single.count(o.name);
    out.emplace_back(std::move(o), whole);
  }
  return out;
}

// The words of the vocabulary's nouns that mean what a noun among `words` means, and are not
// among them ("a sphere" gives ball, balls, spheres): an object named ball is the plainest sphere,
// so of the objects "a sphere" scores alike it comes first (rankNamesAmongWords). Nouns with a
// shape only ("shape" and "thing" name no geometry).
std::vector<std::string> nounSynonymsOf(const std::vector<std::string>& words, const Vocabulary& vocabulary) {
  std::unordered_set<std::string> meant;
  for (const std::string& w : words)
    if (const Noun* n = vocabulary.noun(w); n && !n->params.is_null()) meant.insert(n->word);
  std::vector<std::string> out;
  if (meant.empty()) return out;
  for (const std::string& w : vocabulary.nounWords()) {
    const Noun* n = vocabulary.noun(w);
    if (n && meant.count(n->word) && std::find(words.begin(), words.end(), w) == words.end()) out.push_back(w);
  }
  return out;
}

// Texts longer than this keep their ties in the search's order (typical first is for the words
// of one part: about forty words).
constexpr size_t kLongestTypicalText = 300;

// How deep the search box reads a linguistic answer again for a named object that its first
// `limit` results leave out: an object named by a word of the text ties with the last result
// more often than not ("a hockey puck": every puck-like object scores 1), and the tie decides.
constexpr size_t kNamedTieDepth = 100;

// How many words of a name ("slightly-bent-rod": 3), all of which are among `words` (or their
// plurals: "spheres" holds sphere); 0 when one is not.
int nameWordsAmong(const std::string& name, const std::vector<std::string>& words) {
  int count = 0;
  size_t from = 0;
  while (from <= name.size()) {
    size_t to = name.find_first_of("-_ ", from);
    if (to == std::string::npos) to = name.size();
    if (to > from) {
      std::string w = name.substr(from, to - from);
      std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return std::tolower(c); });
      if (std::none_of(words.begin(), words.end(), [&](const std::string& t) { return t == w || t == w + "s"; }))
        return 0;
      ++count;
    }
    from = to + 1;
  }
  return count;
}

// Whether a parsed linguistic query (its "condition" tree) holds a relation between components.
bool holdsRelation(const nlohmann::json& node) {
  if (node.is_object()) {
    if (node.value("kind", "") == "relation") return true;
    for (const auto& item : node.items())
      if (holdsRelation(item.value())) return true;
  } else if (node.is_array()) {
    for (const nlohmann::json& item : node)
      if (holdsRelation(item)) return true;
  }
  return false;
}

// Ranks by name among the words of a linguistic text, marked "named" with why in explain. An
// object whose name is the text's content words in another order (objectsNamedByWords) is the
// text's name: score 1. A name of which every word is among the text's words (nameWordsAmong)
// changes no score, since the meaning scores the rest of the text ("a tiny little cube" wants a
// small cube more than the object named cube), but of results with equal scores and coverage the
// named one comes first, and of two, the name of more words: the meaning of "wedge" fits every wedge-like
// object alike, the object named wedge best. An object named by one word of the text that the
// first `limit` results leave out is looked for in the first kNamedTieDepth (`deeper`, when
// given, answers the same request with that limit): it comes in where it ties with the last.
// Not for texts with a relation: their answer is a whole of parts, and each part's name would
// come before it.
//
// Of results with equal scores and coverage, after a whole name, the most typical comes first
// (typical_first.h): the nearest the part `text` makes. Where such a tie runs past the cut, the
// first kNamedTieDepth results are read for the rest of it.
void rankNamesAmongWords(const Store& store, const nlohmann::json& request, const std::vector<std::string>& words,
                         const std::string& text, nlohmann::json* answer, size_t limit,
                         const std::function<nlohmann::json(size_t)>& deeper = nullptr) {
  if (answer->value("search", "") != "linguistic" || !answer->contains("results") ||
      !(*answer)["results"].is_array() || holdsRelation(answer->value("parsed", nlohmann::json::object())))
    return;
  const std::vector<std::string> content = contentWordsOf(words);
  // Ties are broken by the text's words and by its nouns' synonyms ("a sphere": the object named ball).
  const std::vector<std::string> synonyms = nounSynonymsOf(content, activeVocabulary());
  std::vector<std::string> tieWords = words;
  tieWords.insert(tieWords.end(), synonyms.begin(), synonyms.end());
  nlohmann::json& results = (*answer)["results"];
  const auto idOf = [](const nlohmann::json& r) {
    return r.contains("id") && r["id"].is_number_integer() ? r["id"].get<int64_t>() : int64_t{-1};
  };
  std::unordered_map<int64_t, size_t> resultAt;
  for (size_t i = 0; i < results.size(); ++i) resultAt.emplace(idOf(results[i]), i);
  std::vector<int> nameWords(results.size(), 0);
  // How a name breaks ties: twice its words among the text's, so that a name the text says ("a
  // washer": washer) comes before one its noun's synonym gives (disc); else its words among the
  // text's and the synonyms (the object named ball for "a sphere").
  struct Tie {
    int rank;
    bool said;  // the name's words are the text's, not a synonym's
  };
  const auto tieRank = [&](const std::string& name) {
    const int said = nameWordsAmong(name, words);
    return said > 0 ? Tie{2 * said, true} : Tie{nameWordsAmong(name, tieWords), false};
  };
  const auto mark = [&](nlohmann::json& r, const std::string& name, bool whole, bool said) {
    if (whole) r["score"] = 1.0;
    r["named"] = true;
    const std::string how = whole  ? "', the words of the text"
                            : said ? "' among the words of the text"
                                   : "', a synonym of a noun of the text";
    const nlohmann::json why = {{"text", "the name '" + name + how}, {"score", r.value("score", 0.0)}};
    if (!r.contains("explain") || !r["explain"].is_array()) r["explain"] = nlohmann::json::array();
    r["explain"].push_back(why);
  };
  // The lookup first, so that each result is marked once, whole or not.
  const std::vector<std::pair<StoredObject, bool>> found = objectsNamedByWords(store, request, content, synonyms);
  std::unordered_set<int64_t> wholeIds;
  for (const auto& [o, whole] : found)
    if (whole) wholeIds.insert(o.id);
  for (size_t i = 0; i < results.size(); ++i) {
    const std::string name = results[i].value("name", "");
    const bool whole = wholeIds.count(idOf(results[i])) > 0;
    const Tie tie = whole ? Tie{2 * static_cast<int>(content.size()), true} : tieRank(name);
    if (tie.rank == 0) continue;
    nameWords[i] = tie.rank;
    mark(results[i], name, whole, tie.said);
  }
  // Objects the answer left out: a whole name comes in at 1; a name among the words can only tie
  // with the last result, and only where the answer was cut there (not a partial answer, whose
  // scores are another aggregation's).
  const double lastScore = results.empty() ? 0.0 : results.back().value("score", 0.0);
  const bool cut = deeper && results.size() >= limit && !answer->value("partial", false);
  std::optional<nlohmann::json> deep;  // the first kNamedTieDepth results, read once if needed
  for (const auto& [o, whole] : found) {
    if (resultAt.count(o.id)) continue;
    const Tie tie = whole ? Tie{2 * static_cast<int>(content.size()), true} : tieRank(o.name);
    if (whole) {
      results.push_back({{"id", o.id}, {"kind", o.kind}, {"name", o.name}, {"version", o.version}});
    } else {
      if (!cut || tie.rank == 0) continue;
      if (!deep) deep = deeper(kNamedTieDepth);
      const nlohmann::json& deepResults = (*deep)["results"];
      const int64_t id = o.id;  // a structured binding cannot be captured (C++17)
      const auto at = std::find_if(deepResults.begin(), deepResults.end(),
                                   [&](const nlohmann::json& r) { return idOf(r) == id; });
      if (at == deepResults.end() || at->value("score", 0.0) < lastScore) continue;
      results.push_back(*at);
    }
    mark(results.back(), o.name, whole, tie.said);
    nameWords.push_back(tie.rank);
    resultAt.emplace(o.id, results.size() - 1);
  }
  // Typical first, where two results tie on score and coverage.
  const auto tied = [&](const nlohmann::json& a, const nlohmann::json& b) {
    return a.value("score", 0.0) == b.value("score", 0.0) && a.value("coverage", 0.0) == b.value("coverage", 0.0);
  };
  // Whether any two results tie: one sort of their (score, coverage) pairs, not a comparison of
  // every pair (a limit of 1000 made that half a million JSON lookups on every search-box answer).
  std::vector<std::pair<double, double>> keys;
  keys.reserve(results.size());
  for (const nlohmann::json& r : results) keys.emplace_back(r.value("score", 0.0), r.value("coverage", 0.0));
  std::sort(keys.begin(), keys.end());
  const bool ties = std::adjacent_find(keys.begin(), keys.end()) != keys.end();
  // The answer's last result may tie with objects past the cut (with one result, it is unseen).
  const bool tieAtCut = cut && (limit == 1 || tied(results[limit - 2], results[limit - 1]));
  std::vector<double> distance(results.size(), 0.0);
  // Not in closest matches (partial): their order is the mean's, how near each comes. Not for
  // texts longer than a description is (kLongestTypicalText): making their part costs more than
  // the search (a 10,000-word "a round round ... box" took 1.5 s, the search 0.4 s).
  if ((ties || tieAtCut) && !answer->value("partial", false) && text.size() <= kLongestTypicalText) {
    if (const std::optional<std::vector<DescriptorValue>> prototype = wordsPrototype(text)) {
      if (tieAtCut) {
        // The tie at the cut may hold objects the answer left out: read them.
        if (!deep) deep = deeper(kNamedTieDepth);
        const nlohmann::json last = results[limit - 1];
        for (const nlohmann::json& r : (*deep)["results"]) {
          if (!tied(r, last) || resultAt.count(idOf(r))) continue;
          results.push_back(r);
          const Tie tie = tieRank(r.value("name", ""));
          nameWords.push_back(tie.rank);
          if (tie.rank > 0) mark(results.back(), r.value("name", ""), false, tie.said);
          resultAt.emplace(idOf(r), results.size() - 1);
        }
      }
      distance = typicalityDistances(store, results, *prototype, answer->value("parsed", nlohmann::json::object()));
    }
  }
  std::vector<size_t> order(results.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Of equal scores, coverage first (what the descriptors say: the object described as vaguely
  // as the words, QueryScore::coverage), then a whole name, then the most typical, then the name.
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const double sa = results[a].value("score", 0.0), sb = results[b].value("score", 0.0);
    if (sa != sb) return sa > sb;
    const double ca = results[a].value("coverage", 0.0), cb = results[b].value("coverage", 0.0);
    if (ca != cb) return ca > cb;
    const bool wa = wholeIds.count(idOf(results[a])) > 0, wb = wholeIds.count(idOf(results[b])) > 0;
    if (wa != wb) return wa;
    if (nameWords[a] != nameWords[b]) return nameWords[a] > nameWords[b];
    return distance[a] < distance[b];
  });
  nlohmann::json ranked = nlohmann::json::array();
  for (size_t i = 0; i < order.size() && i < limit; ++i) ranked.push_back(std::move(results[order[i]]));
  results = std::move(ranked);
}

// The request's limit as the searches read it (10 by default; an invalid one is theirs to refuse).
size_t requestLimit(const nlohmann::json& request) {
  if (request.contains("limit") && request["limit"].is_number_integer() && request["limit"].get<int64_t>() > 0)
    return static_cast<size_t>(std::min<int64_t>(request["limit"].get<int64_t>(), 1000));
  return 10;
}

// `result` among the answer's results by score, after those of equal or higher score; an object
// already there at a score as high keeps its place, one lower is moved up as `result`. The list
// stays within `limit`.
void mergeByScore(nlohmann::json* answer, const nlohmann::json& result, size_t limit) {
  if (!answer->contains("results") || !(*answer)["results"].is_array()) (*answer)["results"] = nlohmann::json::array();
  nlohmann::json& results = (*answer)["results"];
  const double score = result.value("score", 0.0);
  for (size_t i = 0; i < results.size(); ++i)
    if (results[i].value("id", nlohmann::json()) == result.value("id", nlohmann::json())) {
      if (results[i].value("score", 0.0) >= score) return;
      results.erase(results.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    }
  size_t at = 0;
  while (at < results.size() && results[at].value("score", 0.0) >= score) ++at;
  if (at >= limit) return;
  results.insert(results.begin() + static_cast<std::ptrdiff_t>(at), result);
  if (results.size() > limit) results.erase(results.begin() + static_cast<std::ptrdiff_t>(limit), results.end());
}

// The answer with the named objects first, then its results and the described objects by score
// (stable: a result before a described object of the same score), each object once, up to
// `limit`. An object both found and described keeps its result, at the higher of the two scores,
// marked described, with its own words in explain.
void putWordMatches(nlohmann::json* answer, const nlohmann::json& named, const nlohmann::json& described, size_t limit) {
  if (named.empty() && described.empty()) return;
  nlohmann::json rest =
      answer->contains("results") && (*answer)["results"].is_array() ? (*answer)["results"] : nlohmann::json::array();
  // Objects by id (as JSON text, so that any id type compares), each once: linear in the answer.
  const auto key = [](const nlohmann::json& r) { return r.value("id", nlohmann::json()).dump(); };
  std::unordered_map<std::string, size_t> resultAt;
  for (size_t i = 0; i < rest.size(); ++i) resultAt.emplace(key(rest[i]), i);
  for (const nlohmann::json& d : described) {
    const auto it = resultAt.find(key(d));
    if (it == resultAt.end()) {
      resultAt.emplace(key(d), rest.size());
      rest.push_back(d);
      continue;
    }
    nlohmann::json& r = rest[it->second];
    r["score"] = std::max(r.value("score", 0.0), d["score"].get<double>());
    r["described"] = true;
    if (r.contains("explain") && r["explain"].is_array()) r["explain"].push_back(d["explain"][0]);
  }
  std::stable_sort(rest.begin(), rest.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a.value("score", 0.0) > b.value("score", 0.0);
  });
  nlohmann::json results = nlohmann::json::array();
  std::unordered_set<std::string> seen;
  const auto add = [&](const nlohmann::json& r) {
    if (seen.insert(key(r)).second) results.push_back(r);
  };
  for (const nlohmann::json& n : named) add(n);
  for (const nlohmann::json& r : rest) add(r);
  if (results.size() > limit) results.erase(results.begin() + static_cast<std::ptrdiff_t>(limit), results.end());
  (*answer)["results"] = std::move(results);
}

// The closest matches' steps (degrees each descriptor condition is widened by) and the factor on
// their scores (docs/design/linguistic-search.md, "No dead ends"). 1 reaches every degree from
// any core in [0, 1].
constexpr double kClosestWidening[] = {0.0, 0.125, 0.25, 0.5, 1.0};
constexpr double kClosestDiscount = 0.5;

nlohmann::json searchText(const Store& store, const nlohmann::json& request, const std::string& text,
                          const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                          StoredGraphCache& graphs) {
  const bool csg = isCsgQueryText(text, activeVocabulary());
  nlohmann::json answer = csg ? csgQueryResponse(store, request, csgLimits, graphs)
                              : linguisticQueryResponse(store, request, linguisticLimits);
  answer["search"] = csg ? "csg" : "linguistic";
  // Typical first among a structural search's ties, not for texts longer than a description is
  // (each leaf's part is made).
  if (csg && text.size() <= kLongestTypicalText) orderCsgTiesTypicalFirst(store, graphs, &answer, csgLimits.maxNodes);
  // No object meets every condition (min is 0 for all): the closest partial matches instead, by
  // the mean of the conditions' scores, each marked partial, its explain showing which failed.
  // Not for relations: their mean reads every pair of components of every shape (seconds on the
  // soak's catalogue), where the min's bounds prune.
  const nlohmann::json& parsed = answer.value("parsed", nlohmann::json::object());
  if (csg || !answer["results"].empty() || parsed.value("at_least", 0.0) != 0.0 || request.contains("threshold"))
    return answer;
  const bool relation = parsed.value("condition", nlohmann::json::object()).value("kind", "") == "relation";
  if (parsed.value("aggregation", "") == "min" && !relation) {
    nlohmann::json closest = linguisticQueryResponse(store, request, linguisticLimits, {"mean", std::nullopt});
    if (!closest["results"].empty()) {
      for (nlohmann::json& r : closest["results"]) r["partial"] = true;
      answer["results"] = std::move(closest["results"]);
      answer["partial"] = true;
      return answer;
    }
  }
  // Still nothing (one condition, or every condition failing on every object, or a relation no
  // shape has): the closest matches (query/linguistic/closest_match.h), the conditions widened
  // step by step until some object scores, each relation's placement ignored. Their scores are
  // halved: a closest match is no answer to the words, and explain shows each condition's score
  // as asked beside its closeness.
  const bool placed = holdsRelation(parsed);
  for (const double widenBy : kClosestWidening) {
    if (widenBy == 0.0 && !placed) continue;  // the text's own query, searched above
    nlohmann::json closest = linguisticQueryResponse(store, request, linguisticLimits, {"", widenBy});
    if (closest["results"].empty()) continue;
    for (nlohmann::json& r : closest["results"]) {
      r["score"] = kClosestDiscount * r.value("score", 0.0);
      r["partial"] = true;
    }
    answer["results"] = std::move(closest["results"]);
    answer["partial"] = true;
    answer["closest"] = {{"widened_by", widenBy}, {"placement_ignored", placed}};
    break;
  }
  return answer;
}

// The stored objects named by the text as it was read around its unknown words (readAround-
// UnknownWords' "read_text": without them, or corrected), as named results: "a hockey puck" is
// read as "a puck", and the object named puck is what that names, as it would be for "a puck".
// Scored 1 times the reading's discount (its routed words'); none where a run of the text was
// read (a fragment of it names less than the text). `readWords`: wordsOfText of that "read_text".
nlohmann::json objectsNamedAsRead(const Store& store, const nlohmann::json& request, const nlohmann::json& answer,
                                  const std::vector<std::string>& readWords) {
  if (!answer.contains("read_text") || !answer["read_text"].is_string() || answer.contains("run_discount"))
    return nlohmann::json::array();
  double discount = 1.0;
  if (answer.contains("routed") && answer["routed"].is_array())
    for (const nlohmann::json& r : answer["routed"]) discount *= r.value("discount", 1.0);
  const std::string& read = answer["read_text"].get_ref<const std::string&>();
  nlohmann::json named = objectsNamed(store, request, readWords);
  for (nlohmann::json& n : named) {
    n["score"] = discount;
    n["explain"] = {{{"text", "the name '" + n.value("name", "") + "', the words read ('" + read + "')"},
                     {"score", discount}}};
  }
  return named;
}

// How surely a run of a text's words (KnownWordsReading::window) says what the text means, before
// the share of the text the run holds: below kDescribedScore, so that an object whose own words
// hold every word of the text comes before the meaning of a fragment of it, whatever the share.
constexpr double kRunDiscount = 0.45;

// A text that neither grammar reads (`refused`): read without the words neither knows
// (query/structural/unknown_words.h) or with their corrections; throws `refused`, or a refusal
// naming every unknown word, when that does not read either.
nlohmann::json readAroundUnknownWords(const Store& store, const nlohmann::json& request, const std::string& text,
                                      const std::optional<KnownWordsReading>& known, const Error& refused,
                                      const LinguisticRequestLimits& linguisticLimits,
                                      const CsgRequestLimits& csgLimits, StoredGraphCache& graphs) {
  if (!known || (known->unknown.empty() && known->routed.empty() && !known->window)) throw refused;
  const KnownWordsReading& reading = *known;
  // The text with its typos corrected first (words WordNet does not know, each replaced by a near
  // word of the vocabulary, chosen together so that the text reads): dropping a mistyped "sqare"
  // would lose what the designer said. Then the text without its unknown words; then the longest
  // run of its words that reads.
  std::vector<std::string> tries;
  if (reading.corrected) tries.push_back(*reading.corrected);
  if (!reading.text.empty()) tries.push_back(reading.text);
  if (reading.window) tries.push_back(reading.window->text);
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
  const bool corrected = reading.corrected && searched == *reading.corrected;
  const auto wasCorrected = [&](const UnknownWord& u) {
    return corrected && std::any_of(reading.corrections.begin(), reading.corrections.end(),
                                    [&](const RoutedWord& c) { return c.at == u.at; });
  };
  nlohmann::json ignored = nlohmann::json::array();
  for (const UnknownWord& u : reading.unknown)
    if (!wasCorrected(u)) ignored.push_back({{"word", quotedWord(u.word)}, {"at", u.at}, {"did_you_mean", u.closest}});
  // Read by a run of its words: the known words outside the run are left out too, in text order.
  const bool byRun = reading.window && searched == reading.window->text && searched != reading.text && !corrected;
  if (byRun) {
    for (const UnknownWord& u : reading.window->outside)
      ignored.push_back({{"word", quotedWord(u.word)}, {"at", u.at}, {"did_you_mean", u.closest}});
    std::stable_sort(ignored.begin(), ignored.end(),
                     [](const nlohmann::json& a, const nlohmann::json& b) { return a["at"] < b["at"]; });
  }
  answer["ignored"] = std::move(ignored);
  // Routed words (query/linguistic/word_routes.h) and corrected typos: what each became and why;
  // the text is read less surely through them, so every score is multiplied by their discounts.
  std::vector<RoutedWord> routes = reading.routed;
  if (corrected) {
    routes.insert(routes.end(), reading.corrections.begin(), reading.corrections.end());
    std::stable_sort(routes.begin(), routes.end(), [](const RoutedWord& a, const RoutedWord& b) { return a.at < b.at; });
  }
  nlohmann::json routed = nlohmann::json::array();
  double discount = 1.0;
  for (const RoutedWord& r : routes) {
    routed.push_back({{"word", quotedWord(r.route.word)}, {"at", r.at}, {"became", r.route.became},
                      {"why", r.route.why}, {"via", r.route.via}, {"discount", r.route.discount}});
    discount *= r.route.discount;
  }
  answer["routed"] = std::move(routed);
  if (byRun) {
    // The run says less than the text: every score is multiplied by kRunDiscount and the share of
    // what the text says that it holds (ReadableRun::share), so that objects whose own words hold
    // the whole text (kDescribedScore) come before what a fragment means.
    const double runDiscount = kRunDiscount * std::min(1.0, reading.window->share);
    answer["run_discount"] = runDiscount;
    discount *= runDiscount;
  }
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

}  // namespace

nlohmann::json queryResponse(const Store& store, const nlohmann::json& request,
                             const LinguisticRequestLimits& linguisticLimits, const CsgRequestLimits& csgLimits,
                             StoredGraphCache& graphs) {
  // The same checks, codes and paths as the two searches' own.
  const std::string& text = requireString(requireField(requireObject(request, ""), "text", ""), "text");
  // A stored object's name ranks first ("snowman", "the dumbbell"), before whatever the words mean;
  // an object whose own words hold every word of the text is among the results.
  const std::vector<std::string> words = wordsOfText(text, activeVocabulary());
  const size_t limit = requestLimit(request);
  const nlohmann::json named = objectsNamed(store, request, words);
  // The full-text lookup only where its answer is used: not on the search's hot path.
  const auto described = [&] { return objectsDescribed(store, request, words, limit); };
  try {
    nlohmann::json answer = searchText(store, request, text, linguisticLimits, csgLimits, graphs);
    // Where the meaning finds something whole, it is the answer: a description's words may meet
    // by chance ("a sharp cylinder" in "a very bent cylinder and a very sharp pyramid").
    const bool found = answer.contains("results") && !answer["results"].empty() && !answer.value("partial", false);
    rankNamesAmongWords(store, request, words, text, &answer, limit, [&](size_t depth) {
      nlohmann::json deeper = request;
      deeper["limit"] = depth;
      return searchText(store, deeper, text, linguisticLimits, csgLimits, graphs);
    });
    putWordMatches(&answer, named, found ? nlohmann::json::array() : described(), limit);
    return answer;
  } catch (const Error& refused) {
    if (refused.code() != errc::kInvalidParameter || refused.path() != "text") throw;
    // Words no grammar reads that are a name: the named objects are the answer.
    const nlohmann::json byWords = described();
    if (!named.empty()) {
      nlohmann::json answer = {{"search", "name"}, {"results", nlohmann::json::array()}};
      putWordMatches(&answer, named, byWords, limit);
      return answer;
    }
    std::optional<KnownWordsReading> reading;
    try {
      reading = readKnownWords(text, activeVocabulary());
    } catch (const Error&) {
      // a character no query tokenises: refused below as it was
    }
    // Names among the words the grammars lack, or one letter from one ("egg form", "snowmn").
    const nlohmann::json nearly =
        reading ? objectsNearlyNamed(store, request, text, *reading) : nlohmann::json::array();
    try {
      nlohmann::json answer =
          readAroundUnknownWords(store, request, text, reading, refused, linguisticLimits, csgLimits, graphs);
      // Names among the words as written and as read ("sphre" read as "sphere": the object named ball).
      const std::vector<std::string> asRead =
          answer.contains("read_text") && answer["read_text"].is_string()
              ? wordsOfText(answer["read_text"].get<std::string>(), activeVocabulary())
              : std::vector<std::string>{};
      std::vector<std::string> readWords = words;
      for (const std::string& w : asRead)
        if (std::find(readWords.begin(), readWords.end(), w) == readWords.end()) readWords.push_back(w);
      const std::string readText = answer.value("read_text", text);
      rankNamesAmongWords(store, request, readWords, readText, &answer, limit, [&](size_t depth) {
        nlohmann::json deeper = request;
        deeper["limit"] = depth;
        return readAroundUnknownWords(store, deeper, text, reading, refused, linguisticLimits, csgLimits, graphs);
      });
      // A name the text only nearly holds is a guess at an unknown word ("spikes" one letter from
      // the object named spike): it ranks by its score among what the read words found, so "star
      // with spikes" lists the spiky star (1) before the spike (0.8). Named objects of the read
      // words, and near names where the read words find nothing, come first.
      nlohmann::json names = objectsNamedAsRead(store, request, answer, asRead);
      for (const nlohmann::json& n : nearly) mergeByScore(&answer, n, limit);
      putWordMatches(&answer, names, byWords, limit);
      return answer;
    } catch (const Error& unread) {
      if (unread.code() != errc::kInvalidParameter || unread.path() != "text") throw;
      if (!nearly.empty()) {
        nlohmann::json answer = {{"search", "name"}, {"results", nlohmann::json::array()}};
        putWordMatches(&answer, nearly, byWords, limit);
        return answer;
      }
      // Words no grammar reads that objects are described by ("a mushroom form"), or some of them
      // ("a silk ribbon": the object described as a ribbon), as partial matches.
      if (!byWords.empty()) return {{"search", "words"}, {"results", byWords}};
      std::unordered_set<std::string> held;
      nlohmann::json partly = objectsPartlyDescribed(store, request, words, limit, &held);
      if (partly.empty()) throw;
      // The unknown words no result's own words hold are ignored, each with its corrections.
      nlohmann::json ignored = nlohmann::json::array();
      if (reading)
        for (const UnknownWord& u : reading->unknown)
          if (!held.count(u.word))
            ignored.push_back({{"word", quotedWord(u.word)}, {"at", u.at}, {"did_you_mean", u.closest}});
      return {{"search", "words"}, {"results", std::move(partly)}, {"partial", true}, {"ignored", std::move(ignored)}};
    }
  }
}

}  // namespace fsdb
