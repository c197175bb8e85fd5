#pragma once
// The tokens of a linguistic or CSG query text: lower-case words (letters, digits, '-' and '\''),
// numbers as strtod reads them, and the punctuation '(' ')' ','; each with its character offsets,
// so that errors and parsed phrases can point into the text. Two shorthands of notes are read as
// words: "w" and "w/" as "with", '~' as "about".
#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "query/linguistic/vocabulary.h"

namespace fsdb::query_tokens {

struct Token {
  std::string text;  // lower case
  size_t offset;     // character position in the query text
  size_t end;
  bool number = false;
};

// Tokens [begin, begin + n) of a tokenised text, read by a parser (which may own them).
struct TokenView {
  const Token* data = nullptr;
  size_t n = 0;
  size_t size() const { return n; }
  bool empty() const { return n == 0; }
  const Token& operator[](size_t i) const { return data[i]; }
};

// The tokens of text[from, to) (to <= text.size()), as if the text ended at `to`.
// Throws fsdb::Error(errc::kInvalidParameter, path "text") on a bad number or a character that
// is none of the above, naming its position.
std::vector<Token> tokenize(const std::string& text, size_t from, size_t to);

// Function words that carry no property of a shape: articles, conjunctions, prepositions, "is",
// "has" and the like ("a", "and", "with", "of", "its", "for"). One list for the readers that set
// them aside: the full-text search of objects' own words, and the joining words left dangling
// where unknown words are dropped from a text.
bool functionWord(const std::string& word);

// The adjectives that grade a deformation or an extent, each with the intensity term it says:
// slight, small, gentle and mild (slightly), moderate (moderately), strong, big, large, sharp and
// heavy (very), extreme (extremely). The feature phrase reads them before its noun ("a slight
// bend", "a strong twist"), and the word routes read an adverb made from one as its intensity
// ("gently curved", "heavily bent": WordNet's pertainym link from the adverb to the adjective).
const std::vector<std::pair<std::string, std::string>>& degreeWords();

// The words without the vocabulary's fillers ("please"), which carry no meaning wherever they
// stand, and without the comma that sets one off: the one after it ("please, find ...", "round,
// please, tapered"), else the one before it when it ends the text ("small, please"). Word is any
// type with a `text` (the linguistic parser's Token, the CSG phrase parser's words).
template <typename Word>
std::vector<Word> withoutFillers(std::vector<Word> words, const Vocabulary& vocabulary) {
  std::vector<Word> out;
  out.reserve(words.size());
  for (size_t i = 0; i < words.size(); ++i) {
    if (!vocabulary.isFiller(words[i].text))
      out.push_back(std::move(words[i]));
    else if (i + 1 < words.size() && words[i + 1].text == ",")
      ++i;
    else if (i + 1 == words.size() && !out.empty() && out.back().text == ",")
      out.pop_back();
  }
  return out;
}

// The comparison "as WORD as ..." that names a thing to compare with ("as big as a house", "as
// thin as a pencil"), at wordAt(0), wordAt(1), ... (a const std::string*, null past the end): the
// words it spans, 0 when there is none. What is compared with runs to the next comma, and, or,
// with, that, which or but, at most four words.
template <typename WordAt>
size_t comparisonLength(const WordAt& wordAt) {
  constexpr size_t kLongestCompared = 4;
  static const std::vector<std::string> kEnds = {",", "and", "or", "with", "that", "which", "but"};
  const std::string* first = wordAt(0);
  const std::string* second = wordAt(2);
  if (!first || *first != "as" || !wordAt(1) || !second || *second != "as") return 0;
  size_t n = 3;
  while (n < 3 + kLongestCompared && wordAt(n) && std::find(kEnds.begin(), kEnds.end(), *wordAt(n)) == kEnds.end()) ++n;
  return n;
}

// The words without comparisons (comparisonLength) whose word is one of the vocabulary's
// adjectives ("a ball as big as a house", "a rod as thin as a pencil, slightly bent"): the
// adjective alone is kept, plain, since how big a house is is no knowledge of the vocabulary. A
// routed word is one by then: the readers route unknown words before they read (and keep the
// words of a comparison, query/structural/unknown_words.h).
template <typename Word>
std::vector<Word> withoutComparisons(std::vector<Word> words, const Vocabulary& vocabulary) {
  std::vector<Word> out;
  out.reserve(words.size());
  for (size_t i = 0; i < words.size();) {
    const size_t n = comparisonLength([&](size_t k) { return i + k < words.size() ? &words[i + k].text : nullptr; });
    if (n > 0 && vocabulary.adjective(words[i + 1].text)) {
      out.push_back(std::move(words[i + 1]));
      i += n;
      continue;
    }
    out.push_back(std::move(words[i]));
    ++i;
  }
  return out;
}

// The words as the readers take them: withoutFillers, withoutComparisons, and a run of one
// intensity said again and again stepped up the vocabulary's order by one term per repetition, as
// far as the strongest ("very very long" and "very, very long" are extremely long; "really really
// big" too: really is very). People stress
// a word by repeating it; read word by word, the second "very" left the first without its
// adjective and the reading dropped both. The run keeps the first word's place.
template <typename Word>
std::vector<Word> readableWords(std::vector<Word> words, const Vocabulary& vocabulary) {
  words = withoutComparisons(withoutFillers(std::move(words), vocabulary), vocabulary);
  const std::vector<std::string>& order = vocabulary.intensityOrder();
  std::vector<Word> out;
  out.reserve(words.size());
  for (size_t i = 0; i < words.size();) {
    const FuzzyNumber* term = vocabulary.intensity(words[i].text);
    size_t j = i + 1, repeats = 0;
    // "very very" and "very, very".
    for (;;) {
      const size_t k = j < words.size() && words[j].text == "," ? j + 1 : j;
      if (!term || k >= words.size() || vocabulary.intensity(words[k].text) != term) break;
      j = k + 1;
      ++repeats;
    }
    out.push_back(std::move(words[i]));
    if (repeats > 0) {
      size_t at = 0;
      while (at < order.size() && vocabulary.intensity(order[at]) != term) ++at;
      if (at < order.size()) out.back().text = order[std::min(order.size() - 1, at + repeats)];
    }
    i = j;
  }
  return out;
}

// How many words of `phrase` (words separated by one blank) stand at wordAt(0), wordAt(1), ...
// (a const std::string*, null past the end): its length in words, 0 unless all of them do.
template <typename WordAt>
size_t phraseLength(const WordAt& wordAt, const std::string& phrase) {
  size_t k = 0, i = 0;
  while (i < phrase.size()) {
    size_t j = phrase.find(' ', i);
    if (j == std::string::npos) j = phrase.size();
    const std::string* word = wordAt(k);
    if (!word || word->compare(0, std::string::npos, phrase, i, j - i) != 0) return 0;
    ++k;
    i = j + 1;
  }
  return k;
}

// The request that opens a query ("show me", "I am looking for"): the longest of the vocabulary's
// request phrases and the query verbs (with the "for" a verb may take), in words; 0 for none.
// Both parsers skip it, so both read the same requests.
size_t requestLength(const std::function<const std::string*(size_t)>& wordAt, const Vocabulary& vocabulary);

}  // namespace fsdb::query_tokens
