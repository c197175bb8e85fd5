#pragma once
// Linguistic queries (Zhang, Pham & Chen, §5: "find a slightly bent shape"; docs/api.md §5):
// parsing the text into a condition tree over shape descriptors (query/linguistic/descriptors.h)
// and spatial relations (Zhang, Pham & Chen, §2.2), and scoring a part's descriptor values or a
// shape's components against it.
//
// The grammar is schema/query_grammar.ebnf (a test parses every example listed there). In short:
//   query       = [ request ] phrase [ threshold ] [ "using" ("min"|"product"|"mean") ]
//   request     = a request phrase of the vocabulary ("show me", "I am looking for") | verb [ "for" ]
//   phrase      = noun_phrase [ [ distance ] direction_phrase noun_phrase ]
//   noun_phrase = [ article ] [ condition ] noun [ measures ] [ [ "," ] condition ]
//                 [ [ "," ] ("that"|"which") ("is"|"are"|"has"|"have") condition | [ "," ] "with" condition ]
//               | [ article ] pronoun [ condition ] [ relative clause ]     ("something twisted")
//               | condition [ "with" condition ]  (a bare description: first phrase, no article)
// The vocabulary's fillers ("please") are skipped wherever they stand.
//   condition   = conjunct { "or" conjunct };  conjunct = negation { ["and"|","] negation }
//   negation    = "not" negation | "(" condition ")" | descriptor degree | [ intensity ] adjective
//               | adjective intensity_after   ("bent slightly", "twisted a little": Vocabulary::intensityAfter)
//   degree      = [ "is" ] ( number_phrase | "at least" number | "at most" number )
//   threshold   = [ "with" "score" ] "at least" number
// Words are case-insensitive; nouns, adjectives, intensities, directions and distance words come
// from the Vocabulary (query/linguistic/vocabulary.h), so a user's vocabulary file extends the language.
//
// Meaning of the tree:
//   * measure ("about 10 long", "2 across", "between 3 and 4 wide", "3 units tall", "diameter
//     2", "a radius of 1", "4 x 2 x 1", "4 units on a side"): a kDescriptor condition on length,
//     width, thickness or height (descriptors.h) with the extent's set over their degrees; a plain
//     number means "about" it (people measure roughly; "exactly 2" is crisp); three numbers are the
//     sorted extents; a side gives all three. After a noun, measures may follow it directly
//     ("a rod 6 long and 0.2 across"). measureWords() lists the words.
//   * descriptor degree ("bendness at least 0.5"): a kDescriptor condition with the set
//     trap(x, x, 1, 1) (at least), trap(0, 0, x, x) (at most) or the number phrase restricted to
//     [0, 1] ("roundness about 1").
//   * [intensity] adjective: a kDescriptor condition on the adjective's descriptor with the
//     intensity's fuzzy set (plain: μ(d) = d), mirrored d → 1 − d for low-pole adjectives.
//   * a noun: its conditions (a kDescriptor, or a kAnd of them labelled with the noun);
//     "shape", "part", ... have none. LinguisticQuery::subject: "part" for part nouns, "shape" for
//     relations (only shapes have several components), else "any".
//   * and / or / not: kAnd (scores aggregated by LinguisticQuery::aggregation: min, the default,
//     product or mean), kOr (max), kNot (1 − the child's score). A kAnd without children is
//     "anything" (score 1): the condition of a relation's bare noun ("a shape above a cube").
//   * relations: kRelation, children[0] the subject noun phrase, children[1] the other one,
//     `direction` a direction word of the vocabulary ("left", "top right"; phrases such as
//     "above", "in front of" name one), `distance` the fuzzy distance between the centres.
// Scores: a kDescriptor condition scores S(value, set) of docs/api.md §5
// (geometry/fuzzy/fuzzy_similarity.h; for a crisp value μ_set(value)). A relation scores, over
// ordered pairs (i, j) of distinct components, the best min(subject(i), other(j),
// μ_direction(centre_i − centre_j), S(|centre_i − centre_j|, distance)); centres are the
// translations' core midpoints for the direction and the fuzzy translations (exact alpha-cuts of
// the norm) for the distance.
// explain: every condition with text, in pre-order (the and / or nodes carry the text they
// cover), with its score for the component (pair) that gave the total.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/field/boundary_method.h"
#include "geometry/fuzzy/fuzzy_number.h"
#include "geometry/superquadric/fuzzy_part.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
class Vocabulary;  // query/linguistic/vocabulary.h: Vocabulary::builtin() is the compiled-in schema/vocabulary.json

struct QueryCondition {
  enum class Kind { kDescriptor, kAnd, kOr, kNot, kRelation };
  Kind kind = Kind::kDescriptor;
  std::string text;            // the words it came from ("slightly bent"), for explain
  // kDescriptor: the part's descriptor value must match the fuzzy set `set` (S of docs/api.md §5)
  std::string descriptor;
  FuzzyNumber set;
  // kAnd / kOr: children (2 or more); kNot: one child.
  // kRelation: children[0] = the subject part's condition, children[1] = the other part's condition;
  // direction: a direction word of Zhang, Pham & Chen, §2.2 ("left", "top right"); distance
  // optional.
  std::vector<QueryCondition> children;
  std::string direction;
  std::optional<FuzzyNumber> distance;
  // kRelation: the direction's memberships as the parser's vocabulary defines them (when empty,
  // scoring looks `direction` up in activeVocabulary()).
  std::optional<Direction> directionSets;
  // How the words were built, for printing the query back (query/linguistic/query_print.h); no
  // part of the meaning (toJson leaves them out): the noun whose conditions this node holds
  // ("cylinder"), and whether a kAnd joins the parts of one noun phrase (its modifiers, noun and
  // relative clause).
  std::string noun;
  bool nounPhrase = false;
  // An outline adjective's condition ("round", "square": Adjective::outline) not yet turned onto
  // a flat noun's section (Vocabulary::descriptorOn): the noun phrase turns it once its noun is read.
  bool outline = false;
  // Whether it says a part's edges (query/linguistic/edges.h), and how: named by an edge word
  // ("with rounded edges", "sharp corners": Vocabulary::edgeWords) or plainly before a noun with a
  // squariness condition ("a rounded box": Vocabulary::saysEdgesBeforeNouns). It replaces a
  // noun's conditions on the shape of the exponents. `edgeDegree`: the degree of the edge
  // exponents the words say, not yet turned into `set` for the noun (edgeDescriptorSet; a plain
  // adjective before a noun that is not square, or under "not", stays the adjective); the noun
  // phrase turns it once its noun is read.
  enum class Edges { kNone, kNamed, kBeforeNoun };
  Edges edges = Edges::kNone;
  std::optional<FuzzyNumber> edgeDegree;
  // A measure ("about 10 long", "a radius of 1"): the extent it asks for in world units (a
  // radius already doubled) and `set` its image over the descriptor's degrees (extentDegreeSet).
  std::optional<FuzzyNumber> measure;
  // A measured length read as the height, along the axis of a noun turned about its own z axis
  // ("a cylinder with diameter 2 and length 1"): printed back as "long".
  bool axialLength = false;
  // A plain adjective's set (Vocabulary::plainSet of an adjective without a `set` of its own): it
  // ranks by degree and states no degree of its own, so a noun's condition it agrees with stays.
  bool plainRamp = false;
  // A plain adjective and the noun's condition it meets on the same descriptor ("a tapered
  // cylinder": tapered, and the cylinder's "hardly tapered"), where the two can be met together
  // only up to h < 1, the height of their intersection: both score relative to it, min(1, s / h)
  // (the words read as "tapered, as cylinders go": Dubois & Prade's conditioning of a possibility
  // on the noun). It rescales the pair's scores alike, so where the pair decides an object's
  // score (the least under min) no order changes, only what the score says: the most tapered
  // cylinder the words allow scores 1, not h. 1 elsewhere.
  double relativeTo = 1.0;
  // A closest-match query (query/linguistic/closest_match.h): `asked` is the set the words asked
  // where `set` is it widened (a kDescriptor scores on `set` and explains its score on `asked`).
  std::optional<FuzzyNumber> asked;
};
struct LinguisticQuery {
  std::string subject = "any";   // "part", "shape" or "any" (from the noun: "shape" = any)
  QueryCondition root;
  double atLeast = 0.0;          // "at least 0.7": results below are dropped
  std::string aggregation = "min";  // how kAnd combines scores (documented choices)
  // Made by closestMatchQuery (query/linguistic/closest_match.h): every relation scores its two
  // noun phrases only, wherever they stand, and every explain entry gives its score as the words
  // asked (placements included) and its closeness, the relaxed score that ranks.
  bool closestMatch = false;
};
// The server passes activeVocabulary() (query/linguistic/vocabulary.h), so `fsdb serve --vocabulary FILE`
// extends the language.
// Throws fsdb::Error(errc::kInvalidParameter) with path "text" and a message giving the character
// position and the expected words; unknown words name the closest known ones. Conditions nested
// deeper than 64 levels (parentheses, "not") are errc::kLimitExceeded, path "text".
LinguisticQuery parseLinguisticQuery(const std::string& text, const Vocabulary& vocabulary);
// The query with every descriptor condition's set (and `asked`) read over its descriptor's
// degree domain (descriptors.h: degreeDomain, degree_sets.h: withinDegrees): what the searches
// score and plan with, since every stored degree is clamped into the same domain. Where a domain
// is [0, 1] the set is kept as it is (a widened closest-match set reaching below 0 too); the
// `parsed` answers keep the words' sets.
LinguisticQuery withinDegreeDomains(const LinguisticQuery& query);
// Whether the text is a linguistic query: parseLinguisticQuery would not throw. Cheaper on texts
// that are not (no "did you mean" is looked for), for routing texts between the two searches.
bool isLinguisticQuery(const std::string& text, const Vocabulary& vocabulary);

// Whether the linguistic grammar knows `word` (lower case): a word of the vocabulary, of the
// grammar itself ("that", "at least") or a descriptor name. The parser's "unknown word" is one it
// does not.
bool knowsLinguisticWord(const std::string& word, const Vocabulary& vocabulary);
// The words a misspelt word may be corrected to, sorted: the descriptor names and the words of the
// vocabulary's intensities, adjectives, nouns, directions, distances and sections, without the
// grammar's little words and words under three letters ("purple" is no typo of "are").
std::vector<std::string> correctableWords(const Vocabulary& vocabulary);

// The words of measures, sorted: the dimension words after a number ("long", "across", "in
// diameter", "on a side", ...; single words of the phrases) and before one ("diameter",
// "radius", "length", ...), with "x", "by", "unit", "units".
const std::vector<std::string>& measureWords();

// The grammar's opening verbs (each may be followed by "for") and its articles, in the grammar's
// order; the phrase form of structural queries (query/structural/csg_query_text.h) opens with the same verbs
// and names operations after the same articles.
const std::vector<std::string>& queryVerbs();
const std::vector<std::string>& queryArticles();

// The noun phrase that starts at character `from` of `text` (a leaf of a structural query,
// query/structural/csg_query_text.h), read up to character `to` at most (npos: the end): the production
// noun_phrase of the grammar, ending after its noun and relative clause. There an "and", "or" or
// "," that is not followed by the start of a condition ends the phrase (it is the caller's word:
// "the union of a cylinder that is bent and a cube"). Returns the phrase as a query (subject,
// root; no threshold) and the character just after its last word. Errors as parseLinguisticQuery,
// with positions in `text`; when the words before `to` end too early, the message says so.
struct NounPhraseAt {
  LinguisticQuery query;
  size_t end = 0;
};
NounPhraseAt parseNounPhraseAt(const std::string& text, size_t from, size_t to, const Vocabulary& vocabulary);

// parseNounPhraseAt(text, from, npos, vocabulary) for many phrases of one text (the leaves of a
// phrase-form CSG query): the text is tokenised once, at the first call, from its `from` on, not
// again at every phrase (which made a list of n operands quadratic). Calls with ascending `from`
// reuse the tokens; each gives exactly what parseNounPhraseAt gives. `text` and `vocabulary` must
// outlive the reader.
class NounPhraseReader {
 public:
  NounPhraseReader(const std::string& text, const Vocabulary& vocabulary);
  ~NounPhraseReader();
  NounPhraseReader(const NounPhraseReader&) = delete;
  NounPhraseReader& operator=(const NounPhraseReader&) = delete;
  NounPhraseAt at(size_t from);

 private:
  struct Tokens;
  const std::string& text_;
  const Vocabulary& vocabulary_;
  std::unique_ptr<Tokens> tokens_;
};

// The words of a part described by words ("a slightly bent cylinder", "a long, very twisted
// box"): [ article ] adjectives noun { measure } [ [ "," ] adjectives ] [ "with" edge ], adjectives
// = { [ intensity ] adjective [ intensity after it ] [ "," | "and" ] }: adjectives after the noun
// and an intensity after its adjective as a query reads them ("a cylinder, slightly bent", "a box
// twisted a little"). The pointers point into `vocabulary`. Measures may follow the noun ("a pole
// about 10 long"). Errors as
// parseLinguisticQuery (path "text"). query/document/part_from_words.h turns it into parameters.
struct AdjectiveUse {
  const Adjective* adjective;
  const FuzzyNumber* intensity;  // null: the plain adjective
  std::string text;              // "slightly bent"
  // A plain adjective on a descriptor of which the noun keeps its own condition (as the same
  // words read as a query keep it): that condition's set. The query asks for both, so the part
  // takes a degree where both are highest ("a tapered cylinder": as tapered as a cylinder is).
  std::optional<FuzzyNumber> nounSet = std::nullopt;
};
// The edges of a part described by words ("a box with rounded edges", "a rounded box", "a
// cylinder with sharp edges"): the degree of its edge exponents (query/linguistic/edges.h).
struct EdgeUse {
  FuzzyNumber degree;
  std::string text;  // "rounded edges"
};
// A measure of a part described by words ("a skinny pole about 10 long"): the descriptor
// (length, width, thickness, height) and the extent in world units.
struct MeasureUse {
  std::string descriptor;
  FuzzyNumber extent;
  std::string text;  // "about 10 long"
};
struct PartDescription {
  const Noun* noun = nullptr;
  std::vector<AdjectiveUse> adjectives;
  std::vector<MeasureUse> measures;  // after the noun: [ "," ] measure { ( "," | "and" ) measure }
  // After the measures: a "with" edge phrase; or a before_nouns adjective, plain or with an intensity.
  std::optional<EdgeUse> edges;
  // The noun has a condition on its proportions (elongation, flatness, slenderness) that the
  // words keep, as the same words read as a query keep it, or the words say one themselves ("a
  // short thick cylinder"): one extent asked for scales the part.
  bool keepsProportions = false;
};
PartDescription parsePartDescription(const std::string& text, const Vocabulary& vocabulary);

struct ConditionScore {
  std::string text;
  double score;
  std::string component;  // scoreShape: the component path(s) it was scored on ("a, b" for relations)
  // A closest-match query (LinguisticQuery::closestMatch): `score` is what the words asked,
  // `closeness` what the relaxed condition scored (and ranked by).
  std::optional<double> closeness = std::nullopt;
};
// coverage breaks ties of score: the least, over the descriptor conditions the words say of the
// part itself (not a noun's defaults, nothing under "not" or in a relation), of how much of the
// condition's set the value spans (geometry/fuzzy/fuzzy_similarity.h: |A∩B| / |B|, 0 for a crisp
// value); "or" takes the largest. 0 when the words say no such condition (saysVagueness). So of
// two parts that both score 1 for "a slightly bent cylinder", the one whose bend is "slightly
// bent" itself comes before a crisp one that happens to be bent so.
struct QueryScore {
  double score = 0.0;
  std::vector<ConditionScore> explain;
  double coverage = 0.0;
};
// Whether `c` says a descriptor condition of the part itself, one that coverage reads: outside
// every noun's defaults, "not" and relation.
bool saysVagueness(const QueryCondition& c);
// Score of one part's descriptor values (docs/api.md §5; kRelation conditions score 0 for a lone
// part).
QueryScore scoreDescriptors(const LinguisticQuery& query, const std::vector<DescriptorValue>& values);

// One leaf of a stored shape, with its placement resolved (the leaf part's own transform and the
// leaf transform; references expanded).
struct ShapeComponent {
  std::string path;                 // JSON path of the leaf in the shape's document tree
  FuzzyPart part;                   // parameters and placement (tx, ty, tz, ...)
  std::vector<DescriptorValue> descriptors;  // describePart(part)
};
// Score of a shape: descriptor conditions score the best component (max over components, explain
// names it); relations score the best ordered pair of distinct components (subject condition,
// other condition, direction of the offset between their centres, distance).
QueryScore scoreShape(const LinguisticQuery& query, const std::vector<ShapeComponent>& components);

// The leaves of a parsed CSG tree as components, in pre-order; paths "tree", "tree.children[1]",
// "tree.children[1].children[0]", ... (positions in the resolved tree: a referenced shape's
// leaves continue below the leaf that references it). A subtree shared in the DAG (a stored
// shape referenced several times, parsed once) gives its leaves once, at its first occurrence:
// linear in the DAG, never its expansion; scores are the same (linguistic_score.cpp).
std::vector<ShapeComponent> shapeComponents(const CsgTree& tree);

// The fuzzy distance between the centres of two parts (exact alpha-cuts of the norm of the
// difference of their fuzzy translations).
FuzzyNumber centreDistance(const FuzzyPart& a, const FuzzyPart& b);

// How well `subject` is placed against `other` as a relation says (Zhang, Pham & Chen, §2.2):
// min(μ_direction(centre_subject − centre_other), S(centreDistance, distance) when a distance is
// given), centres the translations' core midpoints. Relations of linguistic queries and of CSG
// texts (query/structural/csg_relations.h) are both scored by it.
double relationMembership(const Direction& direction, const std::optional<FuzzyNumber>& distance,
                          const FuzzyPart& subject, const FuzzyPart& other);

// The parsed query as JSON, for the "parsed" member of POST /query/linguistic:
// {"subject","aggregation","at_least","condition":{kind, text, descriptor, set, children,
// direction, distance}}.
nlohmann::json toJson(const LinguisticQuery& query);

// A score's explain as JSON: [{"text","score","component","closeness"}] ("component" and
// "closeness" only when set), for the "explain" member of a result.
nlohmann::json explainJson(const QueryScore& score);

}  // namespace fsdb
