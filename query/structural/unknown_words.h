#pragma once
// brief: The words of a search-box text that neither query grammar knows, the text read without
// them, and one correction of them all chosen together, so that an unknown word is not a dead end
// (docs/api.md §4 POST /query: "ignored", "read_text", "did_you_mean").
// note: A word the grammars lack is first routed (query/linguistic/word_routes.h: its lemma, a verb
// of assembly, WordNet's links onto the vocabulary); only a word with no route is unknown.
// A word is unknown when it is a word of letters (two or more characters, not a number) that
// knowsLinguisticWord, the vocabulary's hole words and csgPhraseWords all lack; a hyphenated word counts by its first part
// ("sphere-shaped"). Leaving words out of a text can leave a joining word with nothing to join
// ("a round plate with purple dots" -> "a round plate with"): such words, when only unknown words
// followed them, go too. Formulas ("A + B") are not read this way: their unknown words are names.
// throws: fsdb::Error(invalid_parameter, path "text") for a character no query tokenises (the
// tokenizer's error).
#include <optional>
#include <string>
#include <vector>

#include "query/linguistic/vocabulary.h"
#include "query/linguistic/word_routes.h"

namespace fsdb {

struct UnknownWord {
  std::string word;                  // lower case, as the tokenizer gives it
  size_t at = 0;                     // its character offset in the text
  std::vector<std::string> closest;  // at most 3 correctable words within plausibleTypoDistance, nearest first
};

struct RoutedWord {
  WordRoute route;  // what it reads as and why (query/linguistic/word_routes.h)
  size_t at = 0;    // its character offset in the text
};

// A run of a text's words that reads as a query where the whole text does not: the words as read
// (routed words replaced), and the known words outside it, which the search leaves out.
struct ReadableRun {
  std::string text;
  std::vector<UnknownWord> outside;  // their `closest` is empty: they are words the grammars know
  // The share of what the text says that the run holds: its words' weights over all of the text's
  // (a noun of the vocabulary or an unknown word 2, another word 1, a number, comma or function
  // word 0), in (0, 1].
  double share = 1.0;
};

struct KnownWordsReading {
  std::vector<RoutedWord> routed;        // words read through their lemma or WordNet, in text order
  std::vector<UnknownWord> unknown;      // the others, in text order; empty: every word is known or routed
  std::string text;                      // the text with routed words replaced and the unknown ones left out
                                         // (blank when nothing is left)
  // The text with each unknown word replaced by one of its closest words, chosen left to right so
  // that the text still reads as a query (words with no such correction are left out); nullopt
  // when no word could be corrected.
  std::optional<std::string> corrected;
  // The words `corrected` replaces, in text order, each as a route of kind "spelling" to its
  // correction (discount kSpellingDiscount); empty when `corrected` is nullopt.
  std::vector<RoutedWord> corrections;
  // Where neither `text` nor `corrected` reads (a word order or a construction no grammar has: "a
  // square pyramid, base 2 x 2, height 2.4"): the run of consecutive words, unknown ones left out
  // and routed ones replaced, that reads and says the most (its nouns count twice, numbers and
  // function words not at all; then the first): "a square pyramid"; nullopt when none does, or
  // for texts over 1000 characters or 24 words.
  std::optional<ReadableRun> window;
};

// How surely a corrected typo says what was meant: about as surely as a word of the same
// WordNet synset (word_routes.h); a non-word two edits from a vocabulary word may mean another.
constexpr double kSpellingDiscount = 0.95;

// WordNet's base forms of `word` as a noun, verb, adjective or adverb, each once (the word itself
// where it is a lemma): empty when WordNet does not know it, or without WordNet. A word it knows
// is a word the writer meant, not a typo ("pillow" is no misspelt pillar, "wall" no misspelt ball).
std::vector<std::string> dictionaryBaseForms(const std::string& word);

// The reading of `text`. Corrections are looked for among the first 16 unknown words only (each
// costs up to three parses of the text), and no corrected text for texts over 1000 characters.
KnownWordsReading readKnownWords(const std::string& text, const Vocabulary& vocabulary);

}  // namespace fsdb
