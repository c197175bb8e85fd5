#pragma once
// Vocabulary: the words of linguistic queries and of parts described by words (Zhang, Pham & Chen,
// §2.2, §5), loaded from a JSON document users can read and extend. schema/vocabulary.json is the
// built-in one, compiled into the binary (Vocabulary::builtin()); `fsdb serve --vocabulary FILE`
// loads another (Vocabulary::fromFile) and makes it the active one (setActiveVocabulary), which
// GET /vocabulary serves and every parser of the server uses.
//
// The document (schema/vocabulary.json describes each section in words):
//   descriptors   [{name, function, meaning, create}]: documentation of query/linguistic/descriptors.h; the
//                 names must be exactly descriptorNames() in order (the functions are code), or its
//                 first kDescriptorsBeforeSections (files written before the section descriptors).
//   intensities   {order, plain, create, terms{word: fuzzy set over the degree}, synonyms{word: word}}
//                 "very bent" is the term `very` over bendness; plain "bent" searches with `plain`
//                 (`plain` rising to the core of `create`: plainSet) and a part made from it
//                 takes one degree in that core (createdSet).
//   hedges        {"not": text}: `not X` scores 1 − score(X) (query/linguistic/linguistic_query.h).
//   adjectives    {word: {descriptor, pole: "high"|"low", create: fuzzy number, outline: bool,
//                 set: fuzzy number}}: a low-pole adjective ("small", "narrow", "straight") mirrors
//                 its sets, d → 1 − d; an outline adjective ("round", "square") describes a flat
//                 noun's outline, its traverse section (descriptorOn), where the descriptor has a
//                 section descriptor; an adjective with a set names a middle of its descriptor
//                 ("truncated", "blunt": a taper short of a point), which it asks for plain and a
//                 part made from it takes.
//   nouns         {word: {subject: "any"|"part", plural, conditions{descriptor: fuzzy set},
//                 params{a part's params for parts from words}, pronoun: true for words such as
//                 "something" that take their adjectives after them} or {same_as: word, plural}.
//   directions    {beta{name: set over degrees}, gamma{name: set over 0..180}, primary{word:
//                 {beta?, gamma}}, secondary{...}, more{...} (optional: beyond the paper's
//                 eighteen, e.g. "side"), phrases{word(s): direction}} (Zhang, Pham & Chen, §2.2).
//   distances     {words{word: fuzzy number}}; number phrases (query/json/number_phrases.h) too.
//   aggregations  {name: text}: the documented ways `and` combines scores (min, product, mean).
//   holes         {words{word: noun}, plain: noun} (optional): the shape words of holes in structural
//                 queries ("a cube with a cylindrical hole"), and the noun of a hole without one.
//   sections      {words[], descriptors{descriptor: section descriptor}} (optional): "with squarish
//                 traverse section" is squariness read as section-squariness (query/linguistic/descriptors.h).
//   edges         {words[], descriptor, set, before_nouns[], sharp[], sharp_set} (optional): "with
//                 rounded edges" (an adjective of the descriptor, then an edge word) says the shape
//                 of a part's edges, plainly the degree `set`; so do the adjectives `before_nouns`,
//                 plain before a noun with a squariness condition ("a rounded box", "a filleted
//                 cube"); the adjectives `sharp` before an edge word say sharp edges, plainly the
//                 degree `sharp_set` ("a cylinder with sharp edges"). The degree is that of the
//                 part's edge exponents (query/linguistic/edges.h).
//   requests      {phrases[], fillers[]} (optional): the request that may open a query ("show me",
//                 "I am looking for"; the longest that matches is skipped) and the words skipped
//                 wherever they stand ("please").
// Words are lower case; a noun or direction may have several words ("double pyramid").
//
// Errors: fromJson/fromFile throw fsdb::Error(errc::kInvalidDocument) with the JSON path of the bad
// entry ("nouns.cube.conditions.squariness.trap[1]", "adjectives.bent.descriptor"): unknown
// descriptors, bad fuzzy sets, sets leaving [0, 1] for degrees, same_as naming nothing.
// The object is immutable after construction; any number of threads may read it.
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"
#include "geometry/core/vec3.h"

namespace fsdb {

struct Adjective {
  std::string word;
  std::string descriptor;
  bool lowPole = false;                // the adjective names the low end ("small", "narrow")
  std::optional<FuzzyNumber> create;   // the degree of a part made from the plain adjective
  bool outline = false;                // on a flat noun it says the outline: descriptorOn
  // A middle of the descriptor, not a pole ("truncated": a taper short of a point): the set the
  // plain adjective asks for (plainSet), as written; `create` is it unless given.
  std::optional<FuzzyNumber> set;
  // The noun whose shape the adjective names ("cylindrical": cylinder), or empty. Plain, on a noun
  // with no shape of its own or on none, it is that noun ("a cylindrical thing" is a cylinder,
  // not any round-sectioned shape such as a ball); beside a noun with a shape it keeps its
  // descriptor ("a cylindrical box").
  std::string shapeOf;
  // Read where it is written, never reached by a WordNet route (word_routes.h): WordNet's senses
  // of "low" are also of mood and sound ("blue", "gloomy", "crushed" are low there), and a blue
  // box is no flat one.
  bool writtenOnly = false;
};

struct NounCondition {
  std::string descriptor;
  FuzzyNumber set;
};

struct Noun {
  std::string word;                        // the canonical word (same_as resolved)
  std::string subject = "any";             // "any" or "part"
  std::vector<NounCondition> conditions;   // empty: no constraint ("shape")
  nlohmann::json params;                   // null for nouns without a shape ("shape", "part")
  bool pronoun = false;                    // takes its adjectives after it: "something twisted"
  // Whether the noun lies flat on its own z axis: its params' C is under kFlatNounRatio of the
  // shorter of A and B (a plate, a disc, a board; not a dome). Its outline is its traverse
  // section, which outline adjectives then describe ("a round plate": descriptorOn).
  bool flat = false;
};
inline constexpr double kFlatNounRatio = 0.4;

// A direction of Zhang, Pham & Chen, §2.2: a set over beta (XZ plane, degrees, period 360) and/or
// one over gamma (angle from the top, 0..180).
struct Direction {
  std::string word;
  std::optional<FuzzyNumber> beta;
  std::optional<FuzzyNumber> gamma;
};

class Vocabulary {
 public:
  static const Vocabulary& builtin();  // schema/vocabulary.json as compiled in
  static Vocabulary fromJson(const nlohmann::json& doc);
  static Vocabulary fromFile(const std::string& path);

  const nlohmann::json& document() const { return document_; }  // what GET /vocabulary serves

  // Lookups by (lower-case) word; null when unknown. Synonyms and plurals resolve.
  const FuzzyNumber* intensity(const std::string& word) const;
  // An intensity after its adjective ("bent slightly", "twisted a little"): an intensity word or a
  // phrase of intensities.after, which is read only there.
  const FuzzyNumber* intensityAfter(const std::string& words) const;
  const Adjective* adjective(const std::string& word) const;
  const Noun* noun(const std::string& word) const;               // singular or plural
  const Direction* direction(const std::string& word) const;     // a direction word or phrase
  const FuzzyNumber* distance(const std::string& word) const;

  const FuzzyNumber& plain() const { return plain_; }
  const FuzzyNumber& plainCreate() const { return plainCreate_; }
  // The degree set a plain adjective ("bent", no intensity) searches with: its own `set` where it
  // has one (a middle of the descriptor, which a part made from it takes too), else `plain`
  // squeezed to rise to 1 where the core of the adjective's created range begins (its own
  // `create`, else `create`, mirrored for a low pole) and 1 beyond. It ranks by degree up to that
  // knee ("bent" scores a slightly bent part below a moderately bent one), and a part made from
  // the plain adjective, one degree inside the core, scores 1 (docs/design/linguistic-search.md,
  // "Round trips").
  FuzzyNumber plainSet(const Adjective& adjective) const;
  // The degree a part made from words takes for the adjective with `intensity` (null: plain): the
  // intensity's set (mirrored for a low pole); plain, a middle's own create or set, else one
  // degree, the middle of the core of the adjective's own `create` as written, else of `create`
  // mirrored for a low pole.
  FuzzyNumber createdSet(const Adjective& adjective, const FuzzyNumber* intensity) const;
  const std::vector<std::string>& intensityOrder() const { return intensityOrder_; }
  bool isAggregation(const std::string& name) const;

  // Every word and multi-word phrase of each kind, sorted (for messages, tests and the parser);
  // listed once, when the vocabulary is loaded.
  const std::vector<std::string>& intensityWords() const { return intensityWords_; }
  // The intensity words and the phrases of intensities.after: what may follow an adjective.
  const std::vector<std::string>& intensityAfterWords() const { return intensityAfterWords_; }
  const std::vector<std::string>& adjectiveWords() const { return adjectiveWords_; }
  // The comparatives of the adjectives of width, thickness and size ("thinner", "wider",
  // "bigger", "tinier"), by the regular rules: -er, -r after e, -ier for y, and a doubled last
  // consonant after one vowel (thin, slim, big). Sorted; what the parser's taper phrase compares
  // along a part ("gets thinner towards the top").
  const std::vector<std::string>& widthComparatives() const { return widthComparatives_; }
  const std::vector<std::string>& nounWords() const { return nounWords_; }  // singular and plural
  const std::vector<std::string>& directionWords() const { return directionWords_; }
  const std::vector<std::string>& distanceWords() const { return distanceWords_; }
  const std::vector<std::string>& aggregationNames() const { return aggregations_; }
  // The request phrases that may open a query, sorted (the parsers skip the longest that matches),
  // and whether a word is a filler the parsers skip wherever it stands.
  const std::vector<std::string>& requestPhrases() const { return requestPhrases_; }
  bool isFiller(const std::string& word) const { return fillers_.count(word) > 0; }
  // The words of a traverse section ("traverse section", "cross-section") and the descriptor of
  // the section an adjective's descriptor turns into after them (nullptr: none; "with squarish
  // traverse section" reads squariness as section-squariness).
  const std::vector<std::string>& sectionWords() const { return sectionWords_; }
  // The descriptor an adjective's condition is on when it describes `noun` (null: none said): the
  // section descriptor for an outline adjective and a flat noun ("a round plate" is round in
  // outline, its traverse section: section-roundness; "a round ball" is roundness), else its own.
  const std::string& descriptorOn(const Adjective& adjective, const Noun* noun) const {
    if (adjective.outline && noun && noun->flat)
      if (const std::string* section = sectionDescriptor(adjective.descriptor)) return *section;
    return adjective.descriptor;
  }
  const std::string* sectionDescriptor(const std::string& descriptor) const {
    auto it = sectionDescriptors_.find(descriptor);
    return it == sectionDescriptors_.end() ? nullptr : &it->second;
  }
  // The whole-shape descriptor whose section descriptor `section` is (section-squariness:
  // squariness), or nullptr when it is none's.
  const std::string* wholeShapeDescriptor(const std::string& section) const {
    for (const auto& [whole, of] : sectionDescriptors_)
      if (of == section) return &whole;
    return nullptr;
  }
  // The noun a hole's shape word names in structural queries ("cylindrical": cylinder), or
  // nullptr; and the noun of a hole without a word ("a cube with a hole"; empty: none).
  const std::string* holeNoun(const std::string& word) const {
    auto it = holeNouns_.find(word);
    return it == holeNouns_.end() ? nullptr : &it->second;
  }
  const std::string& plainHoleNoun() const { return plainHoleNoun_; }
  // The words of a part's edges ("edges", "corners"; empty: the vocabulary has none), the
  // descriptor that says their shape (roundness), and whether a plain adjective before a noun
  // with a squariness condition says its edges ("a rounded box" is a box with rounded edges,
  // not a round one).
  const std::vector<std::string>& edgeWords() const { return edgeWords_; }
  const std::string& edgeDescriptor() const { return edgeDescriptor_; }
  // The degree of that descriptor rounded edges have, said plainly: the condition of "with
  // rounded edges" and the degree a part made from those words takes.
  const FuzzyNumber& edgeSet() const { return edgeSet_; }
  bool saysEdgesBeforeNouns(const std::string& adjective) const { return edgesBeforeNouns_.count(adjective) > 0; }
  // The adjectives that say sharp edges before an edge word ("sharp edges", "square corners";
  // empty: none), and the degree of the edge descriptor sharp edges have, said plainly.
  const std::vector<std::string>& sharpEdgeWords() const { return sharpEdgeWords_; }
  const FuzzyNumber& sharpEdgeSet() const { return sharpEdgeSet_; }
  bool knowsWord(const std::string& word) const { return words_.count(word) > 0; }
  const std::set<std::string>& words() const { return words_; }

 private:
  nlohmann::json document_;
  FuzzyNumber plain_, plainCreate_;
  std::vector<std::string> intensityOrder_;
  std::map<std::string, FuzzyNumber> intensities_;
  std::map<std::string, std::string> intensitySynonyms_;
  std::map<std::string, std::string> intensitiesAfter_;  // intensities.after: phrase -> term
  std::map<std::string, Adjective> adjectives_;
  std::map<std::string, Noun> nouns_;              // singular
  std::map<std::string, std::string> plurals_;     // plural -> singular
  std::map<std::string, Direction> directions_;    // primary, secondary, phrases
  std::map<std::string, FuzzyNumber> distances_;
  std::vector<std::string> aggregations_;
  std::vector<std::string> requestPhrases_;
  std::set<std::string> fillers_;
  std::vector<std::string> sectionWords_;
  std::map<std::string, std::string> holeNouns_;
  std::string plainHoleNoun_;
  std::map<std::string, std::string> sectionDescriptors_;
  std::vector<std::string> edgeWords_;
  std::string edgeDescriptor_;
  FuzzyNumber edgeSet_;
  std::set<std::string> edgesBeforeNouns_;
  std::vector<std::string> sharpEdgeWords_;
  FuzzyNumber sharpEdgeSet_;
  std::vector<std::string> intensityAfterWords_;
  std::vector<std::string> intensityWords_, adjectiveWords_, nounWords_, directionWords_, distanceWords_;
  std::vector<std::string> widthComparatives_;
  std::set<std::string> words_;
};

// The vocabulary the server's parsers use: builtin() unless setActiveVocabulary was called (once,
// at start-up, before any request; not synchronised).
const Vocabulary& activeVocabulary();
void setActiveVocabulary(Vocabulary vocabulary);

// Zhang, Pham & Chen, §2.2: the membership of a direction for an offset vector
// (X right, Y top, Z front): min(μ_beta(β), μ_gamma(γ)) with β = atan2(z, x) in [0, 360) (beta sets
// are read modulo 360) and γ = the angle from +Y in [0, 180]. A zero offset has no direction: 0.
double directionMembership(const Direction& direction, const Vec3& offset);

// Ranked crisp unit vectors for a direction (defuzzification by local maxima; Bernardes, Wu &
// D'Ottaviano, §5): the local maxima of the beta set and of the gamma set (the beta set read on
// [0, 360)), combined, ranked by min(μ_beta, μ_gamma), best first. "right" gives (1, 0, 0) first.
struct RankedDirection {
  Vec3 vector;
  double mu;
};
std::vector<RankedDirection> directionCandidates(const Direction& direction);

}  // namespace fsdb
