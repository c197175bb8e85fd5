#pragma once
// brief: WordNet: read access to the dictionary files of Princeton WordNet 3.0 (Miller, "WordNet:
// a lexical database for English", CACM 38(11), 1995), which Debian's wordnet-base installs in
// /usr/share/wordnet. word_routes.h uses it to route a designer's words onto the vocabulary: the
// base forms of a word (morphy), its senses in frequency order, and each sense's words and
// pointers (similar-to, antonym, also-see, hypernym).
// note: Nothing is loaded up front. The index files are sorted, so a lemma is found by binary
// search in the mapped file, and a synset's offset is its byte offset in its data file (as
// WordNet's own bin_search and read_synset do); opening maps eight files and reads the three
// exception lists (about 6,000 lines, a few ms). Immutable once open; any number of threads may
// read it.
// throws: nothing; open() answers nullptr (and why) when the directory lacks a file.
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fsdb {

class WordNet {
 public:
  enum class Pos { kNoun, kVerb, kAdjective, kAdverb };

  struct Pointer {
    std::string symbol;   // "&" similar-to, "!" antonym, "^" also-see, "@" hypernym, "@i" instance, ...
    Pos pos = Pos::kNoun;  // the target synset's part of speech (satellites count as adjectives)
    size_t offset = 0;    // the target synset's byte offset in its data file
    int source = 0;       // 1-based word of this synset the pointer is from (0: the whole synset)
    int target = 0;       // 1-based word of the target synset it points to (0: the whole synset)
  };

  struct Synset {
    std::vector<std::string> words;  // lower case, blanks for WordNet's underscores, markers such as "(a)" cut
    std::vector<Pointer> pointers;
    bool satellite = false;          // an adjective satellite ("s"): its head is its "&" pointer
    int lexFile = 0;                 // the lexicographer file: 6 noun.artifact, 17 noun.object, 25 noun.shape, ...
  };

  // The WordNet of the dictionary directory `dir`, or nullptr with *why set when a file is missing.
  static std::unique_ptr<WordNet> open(const std::string& dir, std::string* why = nullptr);
  ~WordNet();
  WordNet(const WordNet&) = delete;
  WordNet& operator=(const WordNet&) = delete;

  // WordNet's morphy: the base forms of `word` (lower case, blanks or underscores) as `pos` that
  // are in the index: the word itself, its exception-list bases ("lying" -> "lie", "thinner" ->
  // "thin"), then the detachment rules ("balls" -> "ball", "resting" -> "rest"; and, beyond
  // morphy, -ier and -iest to -y for adjectives: "curvier" -> "curvy").
  std::vector<std::string> baseForms(const std::string& word, Pos pos) const;

  // The synsets of `lemma` (a base form) as `pos`, most frequent sense first; empty when none.
  std::vector<Synset> senses(const std::string& lemma, Pos pos) const;

  // The synset at a data-file offset (a pointer's target).
  Synset synsetAt(Pos pos, size_t offset) const;

 private:
  WordNet() = default;
  struct Mapped {
    const char* data = nullptr;
    size_t size = 0;
  };
  static constexpr int kPosCount = 4;
  std::string_view indexLine(Pos pos, const std::string& lemma) const;
  Mapped index_[kPosCount];
  Mapped data_[kPosCount];
  std::multimap<std::string, std::string> exceptions_[kPosCount];  // inflected -> base
};

// The WordNet the server's parsers use: opened on first use from setWordNetDirectory's directory,
// else $FSDB_WORDNET, else /usr/share/wordnet; nullptr when that holds no WordNet (then no word
// is routed). Thread-safe.
const WordNet* systemWordNet();
// Where systemWordNet looks ("" : nowhere). Call before the first use (at start-up).
void setWordNetDirectory(const std::string& dir);
// The directory systemWordNet opened or tried, for messages.
std::string wordNetDirectory();

}  // namespace fsdb
