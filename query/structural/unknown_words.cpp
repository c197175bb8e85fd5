#include "query/structural/unknown_words.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include "geometry/core/closest_names.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/word_routes.h"
#include "query/structural/csg_query_text.h"

namespace fsdb {

namespace {

constexpr size_t kCorrectedWords = 16;
// The noun with no shape of its own that stands for an unknown noun after an adjective.
constexpr const char* kPlaceholderNoun = "thing";

// Texts longer than this get each word's closest words but no corrected text: finding it parses
// the whole text up to 49 times (as the linguistic parser's did-you-mean, which stops at the same length).
constexpr size_t kLongestCorrectedText = 1000;

bool knownWordAlone(const std::string& w, const Vocabulary& vocabulary) {
  return knowsLinguisticWord(w, vocabulary) || vocabulary.holeNoun(w) ||
         std::binary_search(csgPhraseWords().begin(), csgPhraseWords().end(), w);
}

// A word either grammar reads. A hyphenated word whose head one reads counts too ("sphere-shaped"
// before "hole" is the CSG phrase's), unless its head is an adjective or it routes as a compound
// (word_routes.h: "low-profile" reads as low): the head alone read nothing, and the reading that
// left the word out took its article with it ("a sharp-edged box" read "box", now "a box").
bool knownWord(const std::string& word, const Vocabulary& vocabulary) {
  if (knownWordAlone(word, vocabulary)) return true;
  const size_t dash = word.find('-');
  if (dash == std::string::npos || !knownWordAlone(word.substr(0, dash), vocabulary)) return false;
  const bool shapedNoun = word.size() > 7 && word.compare(word.size() - 7, 7, "-shaped") == 0;
  if (shapedNoun) return true;
  if (vocabulary.adjective(word.substr(0, dash))) return false;
  const auto alone = [&](const std::string& w) { return knownWordAlone(w, vocabulary); };
  return !routeWord(word, "", vocabulary, systemWordNet(), alone);
}

// Words that only join what follows them to what comes before: left dangling when every word
// after them was unknown.
bool joiningWord(const std::string& w) {
  return w == "," || w == "not" || query_tokens::functionWord(w);
}

bool readsAsQuery(const std::string& text, const Vocabulary& vocabulary) {
  return isLinguisticQuery(text, vocabulary) || isCsgQueryText(text, vocabulary);
}

// `text` with token i replaced by replacement[i] where one is given (nullopt: the token stays; ""
// : it goes, with the blank before it), then blanks collapsed and trimmed.
std::string rewrite(const std::string& text, const std::vector<query_tokens::Token>& tokens,
                    const std::vector<std::optional<std::string>>& replacement) {
  std::string out;
  size_t copied = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!replacement[i]) continue;
    out += text.substr(copied, tokens[i].offset - copied);
    out += *replacement[i];
    copied = tokens[i].end;
  }
  out += text.substr(copied);
  // One blank between words, no blank before a comma, no comma twice or at either end.
  std::string collapsed;
  for (char c : out) {
    const bool blank = std::isspace(static_cast<unsigned char>(c));
    if (blank && (collapsed.empty() || collapsed.back() == ' ')) continue;
    if (c == ',') {
      while (!collapsed.empty() && collapsed.back() == ' ') collapsed.pop_back();
      if (collapsed.empty() || collapsed.back() == ',') continue;
    }
    collapsed += blank ? ' ' : c;
  }
  while (!collapsed.empty() && (collapsed.back() == ' ' || collapsed.back() == ',')) collapsed.pop_back();
  return collapsed;
}

// How much a word of a text says about the shape it means: a noun of the vocabulary (what the
// thing is) 2, another word 1, and nothing for commas, numbers and function words, which say
// something only about the words beside them.
int contentWeight(const std::string& word, bool number, const Vocabulary& vocabulary) {
  if (number || word == "," || word == "(" || word == ")" || query_tokens::functionWord(word)) return 0;
  return vocabulary.noun(word) ? 2 : 1;
}

// The run of consecutive words that reads as a query and says the most (contentWeight; then the
// earliest, then the longest), among the tokens with routed words replaced (replacement[i]
// non-empty) and unknown ones left out; runs neither start nor end at a comma. The words outside
// it are listed with their offsets, and the run's share of the weight of every word of the text
// (unknown ones at 2: what the search could not read may well be what the thing is). At most
// kLongestRunTokens tokens are considered (each run tried costs a parse).
constexpr size_t kLongestRunTokens = 24;

std::optional<ReadableRun> longestReadableRun(const std::vector<query_tokens::Token>& tokens,
                                              const std::vector<std::string>& replacement,
                                              const std::vector<bool>& unknown, const Vocabulary& vocabulary) {
  std::vector<size_t> kept;  // token indices
  for (size_t i = 0; i < tokens.size(); ++i)
    if (!unknown[i] || !replacement[i].empty()) kept.push_back(i);
  if (kept.empty() || kept.size() > kLongestRunTokens) return std::nullopt;
  const auto word = [&](size_t i) { return unknown[i] ? replacement[i] : tokens[i].text; };
  const auto weight = [&](size_t i) {
    return unknown[i] && replacement[i].empty() ? 2 : contentWeight(word(i), tokens[i].number, vocabulary);
  };
  int total = 0;
  for (size_t i = 0; i < tokens.size(); ++i) total += weight(i);
  struct Run {
    size_t from, length;
    int content;
  };
  std::vector<Run> runs;
  for (size_t from = 0; from < kept.size(); ++from) {
    int content = 0;
    for (size_t length = 1; from + length <= kept.size(); ++length) {
      content += weight(kept[from + length - 1]);
      const std::string& w = tokens[kept[from + length - 1]].text;
      if (tokens[kept[from]].text != "," && w != "," && content > 0) runs.push_back({from, length, content});
    }
  }
  std::stable_sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
    return a.content != b.content ? a.content > b.content
                                  : a.from != b.from ? a.from < b.from : a.length > b.length;
  });
  for (const Run& r : runs) {
    std::string run;
    for (size_t k = r.from; k < r.from + r.length; ++k) {
      const std::string w = word(kept[k]);
      run += (run.empty() || w == "," ? "" : " ") + w;
    }
    if (!readsAsQuery(run, vocabulary)) continue;
    ReadableRun out{run, {}, static_cast<double>(r.content) / std::max(1, total)};
    for (size_t i = 0; i < tokens.size(); ++i) {
      const bool inside = i >= kept[r.from] && i <= kept[r.from + r.length - 1];
      if (!inside && tokens[i].text != "," && !(unknown[i] && replacement[i].empty()))
        out.outside.push_back({tokens[i].text, tokens[i].offset, {}});
    }
    return out;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> dictionaryBaseForms(const std::string& word) {
  std::vector<std::string> bases;
  const WordNet* wn = systemWordNet();
  if (!wn) return bases;
  for (WordNet::Pos pos : {WordNet::Pos::kNoun, WordNet::Pos::kVerb, WordNet::Pos::kAdjective, WordNet::Pos::kAdverb})
    for (std::string& base : wn->baseForms(word, pos))
      if (std::find(bases.begin(), bases.end(), base) == bases.end()) bases.push_back(std::move(base));
  return bases;
}

KnownWordsReading readKnownWords(const std::string& text, const Vocabulary& vocabulary) {
  KnownWordsReading reading;
  if (isCsgFormula(text)) {
    reading.text = text;
    return reading;
  }
  const std::vector<query_tokens::Token> tokens = query_tokens::tokenize(text, 0, text.size());
  std::vector<bool> unknown(tokens.size(), false);
  for (size_t i = 0; i < tokens.size(); ++i) {
    const query_tokens::Token& t = tokens[i];
    unknown[i] = !t.number && t.text.size() > 1 && std::isalpha(static_cast<unsigned char>(t.text[0])) &&
                 !knownWord(t.text, vocabulary);
  }
  // A comparison ("as big as a house", "as skinny as a rail") keeps its words: the readers drop
  // the "as" and what is compared with around an adjective (query_tokens::withoutComparisons),
  // and the word between is read, or routed, as any other.
  for (size_t i = 0; i < tokens.size(); ++i) {
    const size_t n = query_tokens::comparisonLength(
        [&](size_t k) { return i + k < tokens.size() ? &tokens[i + k].text : nullptr; });
    if (n == 0) continue;
    for (size_t k = 0; k < n; ++k)
      if (k != 1) unknown[i + k] = false;
    i += n - 1;
  }
  // The text with each unknown word replaced by choice[i] ("": left out), and the joining words
  // that only left-out words follow (up to the end or a comma) left out with them.
  const auto textWith = [&](const std::vector<std::string>& choice) {
    std::vector<std::optional<std::string>> replacement(tokens.size());
    for (size_t i = 0; i < tokens.size(); ++i)
      if (unknown[i]) replacement[i] = choice[i];
    for (size_t i = tokens.size(); i-- > 0;) {
      if (unknown[i] || !joiningWord(tokens[i].text)) continue;
      size_t j = i + 1;
      while (j < tokens.size() && (unknown[j] ? replacement[j]->empty() : replacement[j] && replacement[j]->empty())) ++j;
      if (j > i + 1 && (j == tokens.size() || tokens[j].text == ",")) replacement[i] = "";
    }
    return rewrite(text, tokens, replacement);
  };
  // Routed words (word_routes.h) read as the known word they reach; they are no longer unknown,
  // but keep their replacement in every text below.
  std::vector<bool> routed(tokens.size(), false);
  std::vector<std::string> leftOut(tokens.size());
  const auto known = [&](const std::string& w) { return knownWord(w, vocabulary); };
  for (TokenRoute& r : routeTokens(tokens, [&](size_t i) { return unknown[i]; }, vocabulary, systemWordNet(), known)) {
    routed[r.token] = true;
    leftOut[r.token] = r.route.became;
    reading.routed.push_back({std::move(r.route), tokens[r.token].offset});
  }
  // A noun the vocabulary lacks right after an adjective of the vocabulary stands as "thing" rather than going:
  // "a hollow cylindrical housing" reads "a hollow cylindrical thing" (a cylinder made hollow), where
  // "a hollow cylindrical" reads as neither grammar. It is still listed as ignored.
  std::vector<bool> placeholder(tokens.size(), false);
  const WordNet* wn = systemWordNet();
  const bool placeholders = wn && vocabulary.noun(kPlaceholderNoun);
  for (size_t i = 1; placeholders && i < tokens.size(); ++i) {
    if (!unknown[i] || routed[i]) continue;
    // An adjective as written: a routed one may be a reading of a noun phrase ("with a slight bend"
    // is no slender thing).
    if (unknown[i - 1] || !vocabulary.adjective(tokens[i - 1].text)) continue;
    if (wn->baseForms(tokens[i].text, WordNet::Pos::kNoun).empty()) continue;
    leftOut[i] = kPlaceholderNoun;
    placeholder[i] = true;
  }
  reading.text = textWith(leftOut);

  // Corrections, chosen together: every word its nearest correction first; when that text does not
  // read, each word in turn (left to right) takes the first of its corrections, or none, with which
  // the text, the other words as chosen so far, reads.
  const std::vector<std::string> correctable = correctableWords(vocabulary);
  std::vector<std::string> choice = leftOut;
  std::vector<bool> typo(tokens.size(), false);  // has corrections and is unknown to WordNet
  size_t tried = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!unknown[i] || routed[i]) continue;
    UnknownWord u{tokens[i].text, tokens[i].offset, {}};
    if (tried++ < kCorrectedWords) u.closest = nearestNames(u.word, correctable, 3, plausibleTypoDistance(u.word.size()));
    // A dictionary word is not read as its closest vocabulary word (the closest are still
    // offered); WordNet asked only where it matters.
    typo[i] = !u.closest.empty() && dictionaryBaseForms(u.word).empty();
    if (!u.closest.empty() && typo[i]) choice[i] = u.closest[0];
    reading.unknown.push_back(std::move(u));
  }
  // Where neither the text without its unknown words nor a correction reads: the longest run of
  // its words that does.
  const auto addWindow = [&] {
    if (!reading.corrected && text.size() <= kLongestCorrectedText && !readsAsQuery(reading.text, vocabulary))
      reading.window = longestReadableRun(tokens, leftOut, unknown, vocabulary);
  };
  if (choice == leftOut || text.size() > kLongestCorrectedText) {  // nothing to correct with
    addWindow();
    return reading;
  }
  bool reads = readsAsQuery(textWith(choice), vocabulary);
  for (size_t i = 0, k = 0; i < tokens.size() && !reads; ++i) {
    if (!unknown[i] || routed[i]) continue;
    const std::vector<std::string>& closest = reading.unknown[k++].closest;
    if (!typo[i]) continue;  // a word of the language: left out, never replaced
    std::vector<std::string> options(closest.begin() + (closest.empty() ? 0 : 1), closest.end());
    options.push_back("");
    for (const std::string& option : options) {
      std::vector<std::string> trial = choice;
      trial[i] = option;
      if (readsAsQuery(textWith(trial), vocabulary)) {
        choice = std::move(trial);
        reads = true;
        break;
      }
    }
  }
  if (reads && choice != leftOut) {
    reading.corrected = textWith(choice);
    for (size_t i = 0; i < tokens.size(); ++i)
      if (unknown[i] && !routed[i] && !placeholder[i] && !choice[i].empty())
        reading.corrections.push_back(
            {{tokens[i].text, choice[i], "spelling", tokens[i].text + " -> " + choice[i], kSpellingDiscount},
             tokens[i].offset});
  }
  addWindow();
  return reading;
}

}  // namespace fsdb
