// See query/linguistic/word_routes.h.
#include "query/linguistic/word_routes.h"

#include "geometry/core/closest_names.h"
#include "query/linguistic/query_tokens.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

namespace fsdb {

namespace {

using Pos = WordNet::Pos;

constexpr double kSynonym = 0.95;
constexpr double kSimilarTo = 0.9;
constexpr double kHypernym = 0.9;
constexpr double kAlsoSee = 0.85;
constexpr double kAntonym = 0.85;
constexpr double kDerived = 0.9;
constexpr double kAbbreviation = 0.9;
constexpr double kCompound = 0.9;
constexpr double kPertainym = 0.9;

// WordNet's lexicographer files of nouns that name things with a shape (lexnames(5WN)).
constexpr int kNounArtifact = 6, kNounObject = 17, kNounShape = 25;

// Senses that count, per part of speech (a word's rare senses route nowhere).
size_t sensesThatCount(Pos pos) { return pos == Pos::kNoun ? 4 : 3; }

// Lemmas of verbs whose participles and forms join, cut or rest parts ("glued together", "bored
// through", "resting on"); morphy finds their forms, so each is listed once.
const std::vector<std::string>& joiningVerbs() {
  static const std::vector<std::string> v = {"glue",  "weld",   "fuse",  "attach", "fasten", "bolt",
                                             "rivet", "solder", "stick", "fix",    "connect", "bond"};
  return v;
}
const std::vector<std::string>& cuttingVerbs() {
  static const std::vector<std::string> v = {"bore", "cut", "carve", "punch", "mill", "drill", "pierce", "hollow"};
  return v;
}
const std::vector<std::string>& supportVerbs() {
  static const std::vector<std::string> v = {"rest",  "sit",   "lie",      "stand",  "perch", "balance", "place",
                                             "put",   "set",   "mount",    "stack",  "lay",   "position", "locate",
                                             "situate", "seat", "hang",    "float",  "suspend"};
  return v;
}
const std::vector<std::string>& relationWords() {
  static const std::vector<std::string> v = {"on",     "upon",  "onto",   "atop",   "above",  "over",   "under",
                                             "below",  "beneath", "behind", "in",   "at",     "next",   "beside",
                                             "against", "across", "along", "inside", "within", "to",    "between"};
  return v;
}

bool contains(const std::vector<std::string>& list, const std::string& w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

struct Candidate {
  std::string became;
  std::string why;
  std::string via;
  double discount = 0;
  size_t sense = 0;
  bool noun = false;    // a noun reached from an inflected form ("dowels"): said in the plural
  bool beats(const Candidate& o) const { return discount > o.discount || (discount == o.discount && sense < o.sense); }
};

// A noun of the vocabulary with a shape of its own ("rod", not "thing" or "part").
bool shapeNoun(const Vocabulary& v, const std::string& w) {
  const Noun* n = v.noun(w);
  return n && !n->pronoun && !n->params.is_null();
}

// The adjective that names noun `w`'s shape (shape_of: cone -> conical, ball -> spherical, as a
// synonym of sphere); "" when there is none.
std::string shapeAdjectiveOf(const Vocabulary& v, const std::string& w) {
  const Noun* n = v.noun(w);
  if (!n) return "";
  for (const std::string& a : v.adjectiveWords()) {
    const Adjective* adj = v.adjective(a);
    if (!adj || adj->shapeOf.empty() || adj->word != a) continue;
    const Noun* of = v.noun(adj->shapeOf);
    if (of && of->word == n->word) return a;
  }
  return "";
}

// The known word of `pos` that a WordNet word `w` reaches, with `flip` for an antonym: the
// adjective of the same descriptor at the other pole. Empty when none.
std::string target(const Vocabulary& v, Pos pos, const std::string& w, bool flip) {
  if (pos == Pos::kNoun) return !flip && shapeNoun(v, w) ? w : "";
  if (pos == Pos::kAdverb) return !flip && v.intensity(w) ? w : "";
  if (pos != Pos::kAdjective) return "";
  const Adjective* a = v.adjective(w);
  if (!a || a->writtenOnly) return "";
  if (!flip) return w;
  for (const std::string& other : v.adjectiveWords()) {
    const Adjective* b = v.adjective(other);
    if (b && !b->writtenOnly && b->descriptor == a->descriptor && b->lowPole != a->lowPole && b->word == other)
      return other;
  }
  return "";
}

void consider(Candidate* best, Candidate c) {
  if (!c.became.empty() && (best->became.empty() || c.beats(*best))) *best = std::move(c);
}

// An adverb made from an adjective that grades (query_tokens::degreeWords), as that adjective's
// intensity: "gently" -> gentle -> slightly, "heavily" -> heavy -> very, "strongly" (a known
// intensity already). WordNet's pertainym ("\\") links the adverb to its adjective, `target` its
// word in `adjective` (0: all); an adjective that is no grading word itself may be a synonym of
// one in its first senses or a satellite of one ("greatly" -> great -> large, "severely" ->
// severe -> strong), a step more at that link's discount.
Candidate degreeAdverb(const Vocabulary& v, const WordNet& wn, const std::string& adverb,
                       const WordNet::Synset& adjective, int target, size_t rank) {
  const auto degree = [&](const std::string& w) -> std::string {
    for (const auto& [word, term] : query_tokens::degreeWords())
      if (word == w && v.intensity(term)) return term;
    return "";
  };
  Candidate best;
  for (size_t i = 0; i < adjective.words.size(); ++i) {
    if (target != 0 && target != static_cast<int>(i) + 1) continue;
    const std::string& a = adjective.words[i];
    consider(&best, {degree(a), "WordNet pertainym", adverb + " -> " + a, kPertainym, rank});
    const std::vector<WordNet::Synset> senses = wn.senses(a, Pos::kAdjective);
    for (size_t r = 0; r < senses.size() && r < sensesThatCount(Pos::kAdjective); ++r) {
      for (const std::string& synonym : senses[r].words)
        if (synonym != a)
          consider(&best, {degree(synonym), "WordNet pertainym", adverb + " -> " + a + " = " + synonym,
                           kPertainym * kSynonym, rank});
      for (const WordNet::Pointer& p : senses[r].pointers) {
        if (p.symbol != "&") continue;
        for (const std::string& head : wn.synsetAt(p.pos, p.offset).words)
          consider(&best, {degree(head), "WordNet pertainym", adverb + " -> " + a + " -> " + head,
                           kPertainym * kSimilarTo, rank});
      }
    }
  }
  return best;
}

// The best WordNet route of one base form.
void wordNetRoutes(const Vocabulary& v, const WordNet& wn, const std::string& base, Pos pos, Candidate* best) {
  const std::vector<WordNet::Synset> senses = wn.senses(base, pos);
  for (size_t rank = 0; rank < senses.size() && rank < sensesThatCount(pos); ++rank) {
    const WordNet::Synset& s = senses[rank];
    // A noun's sense routes only where it names a thing of some shape: an artifact, an object or
    // a shape (WordNet's lexicographer files), not a body part or a food ("egg" is no ball).
    if (pos == Pos::kNoun && s.lexFile != kNounArtifact && s.lexFile != kNounObject && s.lexFile != kNounShape) continue;
    // The word's own place in the synset, for its lexical pointers (antonyms are word to word).
    int self = 0;
    for (size_t i = 0; i < s.words.size(); ++i)
      if (s.words[i] == base) self = static_cast<int>(i) + 1;
    for (const std::string& w : s.words)
      if (w != base) consider(best, {target(v, pos, w, false), "WordNet synonym", base + " = " + w, kSynonym, rank});
    for (const WordNet::Pointer& p : s.pointers) {
      if (p.source != 0 && p.source != self) continue;
      if (pos == Pos::kAdverb && p.symbol == "\\") {
        consider(best, degreeAdverb(v, wn, base, wn.synsetAt(p.pos, p.offset), p.target, rank));
        continue;
      }
      const bool similar = p.symbol == "&", also = p.symbol == "^", antonym = p.symbol == "!";
      const bool hypernym = pos == Pos::kNoun && (p.symbol == "@" || p.symbol == "@i");
      if (!similar && !also && !antonym && !hypernym) continue;
      const WordNet::Synset t = wn.synsetAt(p.pos, p.offset);
      const double d = similar ? kSimilarTo : also ? kAlsoSee : antonym ? kAntonym : kHypernym;
      const std::string why = similar ? "WordNet similar-to" : also ? "WordNet also-see" : antonym ? "WordNet antonym" : "WordNet hypernym";
      for (size_t i = 0; i < t.words.size(); ++i) {
        if (p.target != 0 && p.target != static_cast<int>(i) + 1) continue;
        consider(best, {target(v, p.pos, t.words[i], antonym), why, base + " -> " + t.words[i], d, rank});
      }
      // A satellite's head, then the head's antonym ("unbowed" -> straight's... ), and a noun's
      // hypernym's hypernym: one more step, at the product of both discounts.
      if (!similar && !hypernym) continue;
      for (const WordNet::Pointer& q : t.pointers) {
        const bool qAntonym = similar && q.symbol == "!";
        const bool qHypernym = hypernym && (q.symbol == "@" || q.symbol == "@i");
        if (!qAntonym && !qHypernym) continue;
        const WordNet::Synset u = wn.synsetAt(q.pos, q.offset);
        for (size_t i = 0; i < u.words.size(); ++i) {
          if (q.target != 0 && q.target != static_cast<int>(i) + 1) continue;
          const std::string via = base + " -> " + (t.words.empty() ? "" : t.words[0]) + " -> " + u.words[i];
          consider(best, {target(v, q.pos, u.words[i], qAntonym), qAntonym ? "WordNet antonym" : "WordNet hypernym", via,
                          d * (qAntonym ? kAntonym : kHypernym), rank});
        }
      }
    }
  }
}

// The known adjectives that are a verb's past participle, as (verb, adjective) pairs ("bent": bend,
// "curved": curve), in the vocabulary's order; both routes below look a stem or a synonym up in them
// (routeWord builds the list once for both).
using Participles = std::vector<std::pair<std::string, std::string>>;
Participles participleAdjectives(const Vocabulary& v, const WordNet& wn) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& a : v.adjectiveWords()) {
    if (!v.adjective(a)) continue;
    for (const std::string& base : wn.baseForms(a, Pos::kVerb))
      if (base != a) pairs.emplace_back(base, a);
  }
  return pairs;
}

// An adjective behind a verb made from it by -en ("flattened" -> flatten -> flat, "widened" ->
// wide), which WordNet does not link (its derivations join nouns and verbs). Or an adjective made
// from a stem by -y or -ish ("twisty", "pointy", "bendy", "roundish"), which
// WordNet mostly lacks or files under a looser head ("twisty" is similar to crooked, whose
// antonym is straight): the stem itself where it is a known adjective ("roundish" -> round), or
// the known adjective that is the stem's past participle ("twisty" -> twist -> twisted, "bendy"
// -> bend -> bent), or the adjective that names the stem's shape where the stem is a noun
// ("conish" -> cone -> conical; also by -like). Stems as spelt, with a doubled last letter undone
// ("knobby" -> knob) and with an e restored ("curvy" -> curve). Nouns themselves are no targets
// ("party" is not a part).
Candidate derivedAdjective(const Vocabulary& v, const WordNet& wn, const std::string& word,
                           const Participles& participles) {
  // A verb made from an adjective by -en, in any form ("flattened", "widening", "sharpens": flatten,
  // widen, sharpen): the adjective itself ("sharp"), with its e restored ("wide") or its doubled
  // last letter undone ("flat").
  for (const std::string& verb : wn.baseForms(word, Pos::kVerb)) {
    if (verb.size() < 5 || verb.compare(verb.size() - 2, 2, "en") != 0) continue;
    const std::string stem = verb.substr(0, verb.size() - 2);
    std::vector<std::string> adjectives = {stem, stem + "e"};  // "widen": wide
    if (stem.size() >= 3 && stem.back() == stem[stem.size() - 2]) adjectives.push_back(stem.substr(0, stem.size() - 1));
    for (const std::string& adjective : adjectives)
      if (adjective != word && v.adjective(adjective))
        return {adjective, "derivation", word + " -> " + verb + " -> " + adjective, kDerived, 0};
  }
  std::string stem;
  if (word.size() >= 5 && word.compare(word.size() - 3, 3, "ish") == 0) {
    stem = word.substr(0, word.size() - 3);
  } else if (word.size() >= 6 && word.compare(word.size() - 4, 4, "like") == 0) {
    stem = word.substr(0, word.size() - 4);
  } else if (word.size() >= 4 && word.back() == 'y') {
    stem = word.substr(0, word.size() - 1);
  } else {
    return {};
  }
  std::vector<std::string> stems = {stem, stem + "e"};
  if (stem.size() >= 3 && stem[stem.size() - 1] == stem[stem.size() - 2]) stems.push_back(stem.substr(0, stem.size() - 1));
  for (const std::string& s : stems)
    if (s != word && v.adjective(s)) return {s, "derivation", word + " -> " + s, kDerived, 0};
  for (const auto& [base, a] : participles)
    if (std::find(stems.begin(), stems.end(), base) != stems.end())
      return {a, "derivation", word + " -> " + base + " -> " + a, kDerived, 0};
  // A noun whose shape an adjective names: "conish", "coney" -> cone -> conical, "tubey" ->
  // tubular, "conelike" -> conical. By -y or -ish not for an adjective WordNet has with a meaning
  // of its own ("bally" is no round thing); -like always says the noun's likeness.
  const std::vector<std::string> asAdjective = wn.baseForms(word, Pos::kAdjective);
  const bool like = word.compare(word.size() - 4, 4, "like") == 0;
  if (!like && std::find(asAdjective.begin(), asAdjective.end(), word) != asAdjective.end()) return {};
  for (const std::string& s : stems)
    if (const std::string a = shapeAdjectiveOf(v, s); !a.empty())
      return {a, "derivation", word + " -> " + s + " -> " + a, kDerived, 0};
  return {};
}

// A past participle ("flexed", "crushed", "curled") of a verb one of whose first senses has a
// synonym of which a known adjective is the participle: flex = bend -> bent, crush = squash ->
// squashed, curl = curve -> curved; or a fourth or fifth sense that is the synonym's first
// ("stretched": stretch = elongate -> elongated). Only where no other route reaches the vocabulary (WordNet's
// links from adjectives, nouns and adverbs win: "crooked", an adjective, is straight's antonym);
// WordNet has no links from verbs to the vocabulary, so this is the route of a synonym of the
// verb, at a synonym's discount. Not a present participle or
// a third person ("spinning", "bows": a verb's other forms say what a part does, not is).
Candidate synonymVerbParticiple(const WordNet& wn, const std::string& word, const Participles& participles) {
  const auto endsWith = [&](const char* tail) {
    const size_t n = std::char_traits<char>::length(tail);
    return word.size() > n && word.compare(word.size() - n, n, tail) == 0;
  };
  if (endsWith("ing") || endsWith("s")) return {};
  std::vector<std::string> verbs;
  for (const std::string& verb : wn.baseForms(word, Pos::kVerb))
    if (verb != word) verbs.push_back(verb);
  if (verbs.empty()) return {};
  // A later sense counts too where it is the first sense of the synonym, the shape verb's own
  // meaning: stretch's fifth sense is elongate's first ("make long or longer by pulling"), and
  // "stretched" is elongated; "shown" is no "pointed", point's first sense being show's seventh.
  constexpr size_t kLaterSenses = 5;
  Candidate best;
  for (const std::string& verb : verbs) {
    const std::vector<WordNet::Synset> senses = wn.senses(verb, Pos::kVerb);
    for (size_t rank = 0; rank < senses.size() && rank < kLaterSenses; ++rank)
      for (const std::string& synonym : senses[rank].words) {
        if (synonym == verb) continue;
        if (rank >= sensesThatCount(Pos::kVerb)) {
          const std::vector<WordNet::Synset> own = wn.senses(synonym, Pos::kVerb);
          if (own.empty() || own[0].words != senses[rank].words) continue;
        }
        for (const auto& [base, adjective] : participles)
          if (base == synonym && adjective != word)
            consider(&best, {adjective, "WordNet synonym", word + " -> " + verb + " = " + synonym + " -> " + adjective,
                             kSynonym, rank});
      }
  }
  return best;
}

// A word WordNet lacks in every part of speech that begins one shape noun of the vocabulary and
// no other ("cyl" -> cylinder, "pyr" -> pyramid), or, with no noun, one adjective ("rect" ->
// rectangular): a writer in a hurry abbreviates. Three letters at least; a trailing s is a plural
// ("cyls" -> cylinders). Where two nouns begin so ("co": cone, coin) it is no route, nor where a
// word of the vocabulary is a plausible typo away: that is for the corrections ("cylindr" is a
// cylinder misspelt, not cylindrical cut short).
Candidate abbreviated(const Vocabulary& v, const WordNet& wn, const std::string& word) {
  constexpr size_t kShortest = 3;
  for (Pos pos : {Pos::kAdjective, Pos::kNoun, Pos::kAdverb, Pos::kVerb})
    if (!wn.baseForms(word, pos).empty()) return {};
  const size_t typo = plausibleTypoDistance(word.size());
  if (!nearestNames(word, v.nounWords(), 1, typo).empty() || !nearestNames(word, v.adjectiveWords(), 1, typo).empty())
    return {};
  const auto begins = [](const std::string& w, const std::string& a) {
    return w.size() > a.size() && w.compare(0, a.size(), a) == 0;
  };
  // The one word of `words` that `a` begins, counting a noun's plural and synonyms as one word
  // (the shortest spelling that `a` begins: "sph" -> sphere, not spheres); "" when none or two.
  const auto only = [&](const std::vector<std::string>& words, const std::string& a, bool nouns) {
    std::string found, meaning;
    for (const std::string& w : words) {
      if (!begins(w, a) || (nouns ? !shapeNoun(v, w) : !v.adjective(w))) continue;
      const std::string m = nouns ? v.noun(w)->word : w;
      if (!meaning.empty() && meaning != m) return std::string();
      meaning = m;
      if (found.empty() || w.size() < found.size()) found = w;
    }
    return found;
  };
  const bool plural = word.size() > kShortest && word.back() == 's';
  for (const std::string& a : plural ? std::vector<std::string>{word, word.substr(0, word.size() - 1)}
                                     : std::vector<std::string>{word}) {
    if (a.size() < kShortest) continue;
    std::string noun = only(v.nounWords(), a, true);
    if (!noun.empty()) {
      Candidate c{noun, "abbreviation", word + " -> " + noun, kAbbreviation, 0};
      c.noun = a != word;  // said in the plural
      return c;
    }
    if (a != word) continue;  // an adjective has no plural
    const std::string adjective = only(v.adjectiveWords(), a, false);
    if (!adjective.empty()) return {adjective, "abbreviation", word + " -> " + adjective, kAbbreviation, 0};
  }
  return {};
}

// participleAdjectives, listed on first use and then kept: routeTokens routes every unknown word
// of a text with one list (a 10,000-word text of unknown words listed it once per word).
class ParticipleList {
 public:
  ParticipleList(const Vocabulary& v, const WordNet& wn) : v_(v), wn_(wn) {}
  const Participles& get() {
    if (!list_) list_ = participleAdjectives(v_, wn_);
    return *list_;
  }

 private:
  const Vocabulary& v_;
  const WordNet& wn_;
  std::optional<Participles> list_;
};

std::optional<WordRoute> stativeVerb(const std::string& word, const WordNet& wordnet, ParticipleList& participles) {
  for (const std::string& verb : wordnet.baseForms(word, Pos::kVerb))
    for (const auto& [base, adjective] : participles.get())
      if (base == verb && adjective != word)
        return WordRoute{word, "is " + adjective, "stative verb", word + " -> " + verb + " -> " + adjective, 1.0};
  return std::nullopt;
}

std::optional<WordRoute> routeWordWith(const std::string& word, const std::string& next, const Vocabulary& vocabulary,
                                       const WordNet* wordnet, const std::function<bool(const std::string&)>& known,
                                       ParticipleList& participleList);

// A hyphenated compound that no route above reads, by its parts. An adjective with a noun made a
// participle ("sharp-edged", "flat-topped", "thin-walled", "round-ended") describes a feature,
// not the whole: a sharp-edged box is no pointed one, a flat-topped cone no flat one; no route.
// Else a last part that is (or routes to) an adjective of the vocabulary says what the compound
// says ("wafer-thin", "paper-thin", "extra-long"); else a noun with -shaped or -like whose shape an
// adjective names (shape_of: "cylinder-like" -> cylindrical); else a first part that is one
// ("low-profile": a low profile is a low shape). At the part's own discount times kCompound.
Candidate compound(const Vocabulary& v, const WordNet& wn, const std::string& word,
                   const std::function<bool(const std::string&)>& known, ParticipleList& participleList) {
  const size_t first = word.find('-'), last = word.rfind('-');
  if (first == std::string::npos || first == 0 || last + 1 >= word.size()) return {};
  const auto adjectiveOf = [&](const std::string& part) -> Candidate {
    if (v.adjective(part)) return {part, "compound", word + " -> " + part, kCompound, 0};
    const std::optional<WordRoute> r = routeWordWith(part, "", v, &wn, known, participleList);
    if (!r || !v.adjective(r->became)) return {};
    return {r->became, "compound", word + " -> " + part + " -> " + r->became, kCompound * r->discount, 0};
  };
  const std::string tail = word.substr(last + 1), head = word.substr(0, first);
  if (tail == "shaped" || tail == "like") {
    const std::string a = shapeAdjectiveOf(v, head);
    if (a.empty()) return {};
    return {a, "compound", word + " -> " + head + " -> " + a, kCompound, 0};
  }
  Candidate headAdjective = adjectiveOf(head);
  const bool participle = tail.size() > 3 && tail.compare(tail.size() - 2, 2, "ed") == 0;
  if (participle && !headAdjective.became.empty()) return {};
  Candidate c = adjectiveOf(tail);
  return c.became.empty() ? headAdjective : c;
}

std::optional<WordRoute> routeWordWith(const std::string& word, const std::string& next, const Vocabulary& vocabulary,
                                       const WordNet* wordnet, const std::function<bool(const std::string&)>& known,
                                       ParticipleList& participleList) {
  if (!wordnet || word.size() < 2 || !std::all_of(word.begin(), word.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '-' || c == '\''; }))
    return std::nullopt;
  const Pos order[] = {Pos::kAdjective, Pos::kNoun, Pos::kAdverb, Pos::kVerb};
  // Lemmas: an inflection of a word the grammars know. Not a verb's, where WordNet has the word as
  // an adjective of its own: "towering" is an adjective (of great height), not the verb "tower"
  // that would read as the noun.
  const std::vector<std::string> asAdjective = wordnet->baseForms(word, Pos::kAdjective);
  const bool adjectiveItself = std::find(asAdjective.begin(), asAdjective.end(), word) != asAdjective.end();
  for (Pos pos : order) {
    if (pos == Pos::kVerb && adjectiveItself) continue;
    for (const std::string& base : wordnet->baseForms(word, pos))
      // Not to a function word: "as" is no plural of "a".
      if (base != word && known(base) && !query_tokens::functionWord(base)) return WordRoute{word, base, "lemma", base, 1.0};
  }
  // Verbs of assembly, by their lemmas.
  for (const std::string& base : wordnet->baseForms(word, Pos::kVerb)) {
    if (contains(joiningVerbs(), base) && known("joined")) return WordRoute{word, "joined", "joining verb", base, 1.0};
    if (contains(cuttingVerbs(), base) && known("drilled")) return WordRoute{word, "drilled", "cutting verb", base, 1.0};
    if (contains(supportVerbs(), base) && contains(relationWords(), next))
      return WordRoute{word, "", "support verb", base, 1.0};
  }
  // WordNet's links from the word's own base forms.
  Candidate best;
  for (Pos pos : {Pos::kAdjective, Pos::kNoun, Pos::kAdverb})
    for (const std::string& base : wordnet->baseForms(word, pos)) {
      Candidate before = best;
      wordNetRoutes(vocabulary, *wordnet, base, pos, &best);
      if (best.became != before.became || best.via != before.via) best.noun = pos == Pos::kNoun && base != word;
    }
  // After WordNet's own links, which win a tie ("curvy" is similar to curved in WordNet too).
  const Participles& participles = participleList.get();
  {
    Candidate before = best;
    consider(&best, derivedAdjective(vocabulary, *wordnet, word, participles));
    if (best.became != before.became) best.noun = false;
  }
  if (best.became.empty()) best = synonymVerbParticiple(*wordnet, word, participles);
  if (best.became.empty()) best = abbreviated(vocabulary, *wordnet, word);
  if (best.became.empty()) best = compound(vocabulary, *wordnet, word, known, participleList);
  if (best.became.empty()) return std::nullopt;
  if (best.noun) {
    // The plural the vocabulary gives the noun reached ("wands" -> rods).
    const nlohmann::json& nouns = vocabulary.document().value("nouns", nlohmann::json::object());
    const auto it = nouns.find(best.became);
    if (it != nouns.end() && it->is_object() && it->contains("plural") && (*it)["plural"].is_string())
      best.became = (*it)["plural"].get<std::string>();
  }
  return WordRoute{word, best.became, best.why, best.via, best.discount};
}

}  // namespace

std::optional<WordRoute> routeWord(const std::string& word, const std::string& next, const Vocabulary& vocabulary,
                                   const WordNet* wordnet, const std::function<bool(const std::string&)>& known) {
  if (!wordnet) return std::nullopt;
  ParticipleList participles(vocabulary, *wordnet);
  return routeWordWith(word, next, vocabulary, wordnet, known, participles);
}

std::optional<WordRoute> routeStativeVerb(const std::string& word, const Vocabulary& vocabulary, const WordNet& wordnet) {
  ParticipleList participles(vocabulary, wordnet);
  return stativeVerb(word, wordnet, participles);
}

std::vector<TokenRoute> routeTokens(const std::vector<query_tokens::Token>& tokens,
                                    const std::function<bool(size_t)>& unknown, const Vocabulary& vocabulary,
                                    const WordNet* wordnet, const std::function<bool(const std::string&)>& known) {
  std::vector<TokenRoute> out;
  if (!wordnet) return out;
  ParticipleList participles(vocabulary, *wordnet);
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!unknown(i)) continue;
    // Right after "that" or "which" a shape verb says what the part is: "a rod that tapers".
    if (i > 0 && (tokens[i - 1].text == "that" || tokens[i - 1].text == "which"))
      if (std::optional<WordRoute> r = stativeVerb(tokens[i].text, *wordnet, participles)) {
        out.push_back({i, std::move(*r)});
        continue;
      }
    const std::string next = i + 1 < tokens.size() ? tokens[i + 1].text : "";
    std::optional<WordRoute> r = routeWordWith(tokens[i].text, next, vocabulary, wordnet, known, participles);
    if (r) out.push_back({i, std::move(*r)});
  }
  return out;
}

std::optional<RoutedText> routeUnknownWords(const std::string& text, const Vocabulary& vocabulary, const WordNet* wordnet,
                                            const std::function<bool(const std::string&)>& known) {
  const std::vector<query_tokens::Token> tokens = query_tokens::tokenize(text, 0, text.size());
  const auto unknown = [&](size_t i) { return !tokens[i].number && !known(tokens[i].text); };
  std::vector<TokenRoute> routes = routeTokens(tokens, unknown, vocabulary, wordnet, known);
  if (routes.empty()) return std::nullopt;
  RoutedText out;
  size_t copied = 0;
  for (TokenRoute& r : routes) {
    const query_tokens::Token& t = tokens[r.token];
    size_t from = t.offset;
    if (r.route.became.empty())
      while (from > copied && text[from - 1] == ' ') --from;  // the blank before it goes too
    out.text += text.substr(copied, from - copied) + r.route.became;
    copied = t.end;
    out.routes.push_back(std::move(r.route));
  }
  out.text += text.substr(copied);
  return out;
}

}  // namespace fsdb
