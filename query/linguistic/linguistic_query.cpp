// The parser of linguistic queries (query/linguistic/linguistic_query.h, schema/query_grammar.ebnf):
// recursive descent over word tokens (query_tokens.h), one function per production. The JSON
// of a parsed query is linguistic_query_json.cpp.
#include "query/linguistic/linguistic_query.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <mutex>
#include <set>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/json/fuzzy_json.h"
#include "query/json/number_phrases.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/edges.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

using Kind = QueryCondition::Kind;
using query_tokens::Token;
using query_tokens::TokenView;
using query_tokens::tokenize;
using query_tokens::requestLength;
using query_tokens::readableWords;

// A did-you-mean quotes the whole text back; past this many bytes it would be no help to read.
constexpr size_t kLongestSuggestedText = 1000;

// The words of the grammar itself (the vocabulary supplies the rest).
const std::vector<std::string>& grammarWords() {
  static const std::vector<std::string> words = {
      "find", "show", "search", "for", "get", "list", "a", "an", "the", "any", "some", "all",
      "that", "which", "is", "are", "has", "have", "and", "or", "not", "to", "of", "with", "score", "at", "least", "most",
      "using", "min", "product", "mean",
      "exactly", "about", "around", "approximately", "roughly", "between"};
  return words;
}

// Feature phrases, a deformation said as a noun: "with a slight bend" is slightly bent, "a box
// with a twist" a twisted box. Each noun with the participle adjective it stands for (where the
// vocabulary has that adjective), graded by query_tokens::degreeWords ("a slight bend", "a strong
// twist", "an extreme taper"); plain without one. Not "little": it is
// no word of the grammar, so the search box reads it as small, its WordNet route ("a little
// ball"), which grades a feature as well.
const std::vector<std::pair<std::string, std::string>>& featureNouns() {
  static const std::vector<std::pair<std::string, std::string>> words = {
      {"bend", "bent"}, {"curve", "curved"}, {"twist", "twisted"}, {"taper", "tapered"}};
  return words;
}

// The deepest nesting of parentheses and "not" a query may have.
constexpr int kMaxNesting = 64;

const std::vector<std::string> kApproximately = {"exactly", "about", "around", "approximately", "roughly"};

bool contains(const std::vector<std::string>& list, const std::string& w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

std::string joinList(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

QueryCondition descriptorCondition(const std::string& descriptor, FuzzyNumber set, std::string text) {
  QueryCondition c;
  c.kind = Kind::kDescriptor;
  c.descriptor = descriptor;
  c.set = std::move(set);
  c.text = std::move(text);
  return c;
}

// Measures (see the header): the words after a number and before one, each with the descriptor
// it measures (descriptors.h) and the factor from the number to the extent (a radius is half a
// width); "cube" measures all three extents ("4 units on a side"), "section" the two shorter
// ("section 0.4").
struct DimensionWord {
  std::string words;
  std::string descriptor;
  double factor;
};

const std::vector<DimensionWord>& dimensionsAfterNumber() {
  static const std::vector<DimensionWord> d = {
      {"long", "length", 1},        {"in length", "length", 1},       {"wide", "width", 1},
      {"broad", "width", 1},        {"across", "width", 1},           {"in diameter", "width", 1},
      {"diameter", "width", 1},     {"in width", "width", 1},         {"radius", "width", 2},
      {"in radius", "width", 2},    {"thick", "thickness", 1},        {"deep", "thickness", 1},
      {"in thickness", "thickness", 1}, {"tall", "height", 1},        {"high", "height", 1},
      {"in height", "height", 1},   {"on a side", "cube", 1},         {"on each side", "cube", 1},
      {"side", "cube", 1},          {"sides", "cube", 1},
      // The dimension nouns after their number, as people who learnt another word order say
      // them ("a rod of 6 length", "2 height").
      {"length", "length", 1},      {"width", "width", 1},            {"breadth", "width", 1},
      {"thickness", "thickness", 1}, {"depth", "thickness", 1},       {"height", "height", 1},
      // One number of a section: both its extents, a square or round section that size ("a bar
      // of 0.4 section"; two numbers are "0.6 by 1 cross section").
      {"section", "section", 1},    {"cross section", "section", 1},  {"cross-section", "section", 1}};
  return d;
}

// The words after two numbers ("0.6 by 1 cross section") that make them a section across the
// part's length: its two shorter extents, the thickness and the width. A base or footprint ("a 1
// x 1 base") is the section across the height instead (measure(), measuresAfterNoun()).
const std::vector<std::string>& sectionWords() {
  static const std::vector<std::string> words = {"cross section", "cross-section", "section", "profile",
                                                 "cross sections", "cross-sections", "sections", "profiles",
                                                 "base", "footprint"};
  return words;
}

const std::vector<DimensionWord>& dimensionsBeforeNumber() {
  static const std::vector<DimensionWord> d = {
      {"length", "length", 1},   {"width", "width", 1},         {"breadth", "width", 1},
      {"diameter", "width", 1},  {"radius", "width", 2},        {"thickness", "thickness", 1},
      {"depth", "thickness", 1}, {"height", "height", 1},       {"side", "cube", 1},
      {"section", "section", 1}, {"cross section", "section", 1}, {"cross-section", "section", 1},
      // "base 2 x 2": the two extents across the height, or the width at the base ("base 2").
      {"base", "base", 1},       {"footprint", "base", 1}};
  return d;
}

std::vector<std::string> phrasesOf(const std::vector<DimensionWord>& table) {
  std::vector<std::string> out;
  for (const DimensionWord& d : table) out.push_back(d.words);
  return out;
}

const DimensionWord& dimensionWord(const std::vector<DimensionWord>& table, const std::string& words) {
  for (const DimensionWord& d : table)
    if (d.words == words) return d;
  return table.front();  // not reached: words come from the table
}

// Whether extent `a` is shorter than `b` (by their cores' midpoints): the order in which a
// measure's sides are sorted into thickness, width and length.
bool shorterExtent(const FuzzyNumber& a, const FuzzyNumber& b) {
  return a.core().lo + a.core().hi < b.core().lo + b.core().hi;
}

// The width a base of sides `a` and `b` says when its height is unsaid: it lies between them.
// Which extents a base's sides are depends on the height (a tall pyramid's base is its two
// shorter, a flat one's its two longer), but the middle extent is between them either way.
FuzzyNumber widthOfBase(const FuzzyNumber& a, const FuzzyNumber& b) {
  return FuzzyNumber::trapezoidal(std::min(a.support().lo, b.support().lo), std::min(a.core().lo, b.core().lo),
                                  std::max(a.core().hi, b.core().hi), std::max(a.support().hi, b.support().hi));
}

// A measure's condition: its descriptor with the extent's set over the degrees.
QueryCondition measureCondition(const std::string& descriptor, const FuzzyNumber& extent, std::string text) {
  QueryCondition c = descriptorCondition(descriptor, extentDegreeSet(extent), std::move(text));
  c.measure = extent;
  return c;
}

// The descriptor leaves of a condition tree (under "not" and "or" too).
void collectLeaves(const QueryCondition& c, std::vector<const QueryCondition*>* out) {
  if (c.kind == Kind::kDescriptor) out->push_back(&c);
  for (const QueryCondition& child : c.children) collectLeaves(child, out);
}

// The shape of the exponents: squariness, roundness, bevelness and pinchness of the whole part or
// its section describe one thing (eps1, eps2), so a word on any of them replaces a noun's on all.
bool isExponentShape(const std::string& d) {
  return d == "squariness" || d == "roundness" || d == "bevelness" || d == "pinchness" || d == "section-squariness" ||
         d == "section-roundness";
}

// Whether a noun is square (a condition on squariness): its edges are what "rounded" says
// before it ("a rounded box"; Vocabulary::saysEdgesBeforeNouns).
bool isSquareNoun(const Noun& noun) {
  return std::any_of(noun.conditions.begin(), noun.conditions.end(),
                     [](const NounCondition& c) { return c.descriptor == "squariness"; });
}

// The part's proportions: elongation (a noun's default) and the flatness and slenderness that
// "flat" and "long" say.
bool isProportion(const std::string& d) { return d == "elongation" || d == "flatness" || d == "slenderness"; }

// Whether two sets over the degrees contradict each other: no degree belongs to both (exactly).
bool contradicts(const FuzzyNumber& a, const FuzzyNumber& b) { return heightOfIntersection(a, b) == 0.0; }

// The most that an exponent-shape condition `word` and a noun's kept one on another exponent
// descriptor `noun` ("a round box": roundness and the box's squariness) give together over every
// part: max over eps1, eps2 of min(μ_word, μ_noun) of the two descriptors' degrees, which read the
// exponents alone. On a grid of 0.02 over [0.01, 4]^2, then of 0.001 around its best point (the
// degrees are piecewise linear in the exponents); cached per pair, for texts repeat them.
double exponentShapesMeeting(const QueryCondition& word, const QueryCondition& noun) {
  static std::mutex mutex;
  static std::map<std::string, double> cache;
  const std::string key = word.descriptor + toJson(word.set).dump() + noun.descriptor + toJson(noun.set).dump();
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  const int w = descriptorIndex(word.descriptor), n = descriptorIndex(noun.descriptor);
  PlacedSuperquadric part;
  double best = 0.0, best1 = 1.0, best2 = 1.0;
  const auto at = [&](double e1, double e2) {
    part.params.eps1 = std::clamp(e1, 0.01, 4.0);
    part.params.eps2 = std::clamp(e2, 0.01, 4.0);
    const double m = std::min(word.set.membership(descriptorDegree(w, part)), noun.set.membership(descriptorDegree(n, part)));
    if (m > best) best = m, best1 = part.params.eps1, best2 = part.params.eps2;
  };
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) at(0.01 + 0.02 * i, 0.01 + 0.02 * j);
  const double c1 = best1, c2 = best2;
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j) at(c1 + 0.001 * i, c2 + 0.001 * j);
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() >= 4096) cache.clear();  // bounded: the vocabulary's sets make far fewer pairs
  cache[key] = best;
  return best;
}

// A word the noun's kept condition caps scores relative to the most the two give together, h in
// (0, 1) (QueryCondition::relativeTo), under "and" only (not "not" or "or", whose scores mean
// otherwise): a plain adjective on the condition's descriptor, whose sets meet up to
// h = heightOfIntersection ("a tapered cylinder"); or an exponent word, plain or with an
// intensity, beside an exponent shape on another descriptor, h = exponentShapesMeeting ("a round
// box": the roundest box the words allow scores 1).
void relateToNoun(QueryCondition* word, QueryCondition* noun) {
  if (word->kind == Kind::kAnd) {
    for (QueryCondition& child : word->children) relateToNoun(&child, noun);
    return;
  }
  if (word->kind != Kind::kDescriptor || word->edges != QueryCondition::Edges::kNone) return;
  double h = 1.0;
  if (word->descriptor == noun->descriptor) {
    if (word->plainRamp) h = heightOfIntersection(word->set, noun->set);
  } else if (isExponentShape(word->descriptor) && isExponentShape(noun->descriptor)) {
    h = exponentShapesMeeting(*word, *noun);
  }
  if (!(h > 0.0) || h >= 1.0) return;
  word->relativeTo = std::min(word->relativeTo, h);
  noun->relativeTo = std::min(noun->relativeTo, h);
}

// Whether the words a user says replace a noun's condition (nouns are defaults, not vetoes):
//  * a condition on the same descriptor that contradicts the noun's ("a slightly tapered cone":
//    the cone's own taper is high; "a tapered cylinder" agrees with the cylinder's and both hold),
//    or that states a degree of its own (an intensity, a number, a measure: "a moderately tapered
//    pyramid" is as tapered as it says, which a part made from those words is);
//  * for the shape of the exponents, a condition on any of them when the noun keeps another
//    condition to be itself ("a round plate" stays flat, "a square disc" too), or one with a
//    degree of its own on a noun that is not square ("a very boxy ellipsoid" is as boxy as it
//    says, which a part made from those words is). A square noun is its squareness, so "a round
//    box" and "a very round box" keep the box's and find the roundest boxes (the paper's "a very
//    round box in a cylinder" is a rounded box); so does a sphere for a plain word ("a boxy
//    ball" finds the boxiest balls);
//  * for the shape of the exponents, words on the part's edges ("a box with rounded edges", "a
//    rounded box": QueryCondition::edges), which say that shape themselves;
//  * for the noun's proportions (elongation, flatness, slenderness), words on two or more extents
//    ("a board 8 long and 1 wide", "a thin pole 10 long"), or a dimension adjective with an
//    intensity ("a very thin stick": a part made from it takes that thickness whatever the
//    stick's usual proportions; a measure alone, "a sphere 2 across", keeps them);
//  * for the noun's elongation, a word on flatness or slenderness ("a long plate" is a plank, not
//    a square plate: the words' proportions replace the noun's).
// `graded(c)` says whether a condition states a degree of its own (an intensity, a number or a
// measure; not a plain adjective).
bool overriddenByWords(const NounCondition& condition, const Noun& noun, const std::vector<const QueryCondition*>& said,
                       const std::function<bool(const QueryCondition&)>& graded) {
  const std::string& descriptor = condition.descriptor;
  bool keepsAnother = false;
  for (const NounCondition& c : noun.conditions) keepsAnother = keepsAnother || !isExponentShape(c.descriptor);
  const bool square = isSquareNoun(noun);
  std::set<std::string> extents;
  for (const QueryCondition* c : said) {
    if (c->descriptor == descriptor && (graded(*c) || contradicts(c->set, condition.set))) return true;
    if (isExponentShape(descriptor) && c->edges != QueryCondition::Edges::kNone) return true;  // "a box with rounded edges" is no longer square
    if (isExponentShape(descriptor) && isExponentShape(c->descriptor) && (keepsAnother || (graded(*c) && !square)))
      return true;
    if (descriptor == "elongation" && (c->descriptor == "flatness" || c->descriptor == "slenderness")) return true;
    if (c->descriptor == "length" || c->descriptor == "width" || c->descriptor == "thickness" || c->descriptor == "height") {
      extents.insert(c->descriptor);
      if (isProportion(descriptor) && !c->measure && graded(*c)) return true;
    }
  }
  return isProportion(descriptor) && extents.size() >= 2;
}

// Measures name sorted roles: the thickness is the shortest extent, the width the middle one, the
// length the longest. Where the numbers said for two or three of them contradict that order ("a
// box with diameter 2 and length 1"), they are read sorted, as three sides are ("4 x 2 x 1"): the
// smallest number takes the lowest role said. Without this no part had those extents, and the
// part made from the words, whose maker sets each axis to its number, was not found by them.
// `measures`: the descriptor and extent of each measure (height and the rest are left alone).
void sortMeasuredRoles(const std::vector<std::pair<std::string*, const FuzzyNumber*>>& measures) {
  static const std::vector<std::string> roles = {"thickness", "width", "length"};
  std::vector<std::pair<std::string*, const FuzzyNumber*>> sorted;
  for (const auto& m : measures)
    if (std::find(roles.begin(), roles.end(), *m.first) != roles.end()) sorted.push_back(m);
  const auto mid = [](const FuzzyNumber* e) { return e->core().lo + e->core().hi; };
  const auto rank = [&](const std::string& d) { return std::find(roles.begin(), roles.end(), d) - roles.begin(); };
  std::vector<std::string> said;
  for (const auto& m : sorted) said.push_back(*m.first);
  std::stable_sort(said.begin(), said.end(), [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  std::stable_sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) { return mid(a.second) < mid(b.second); });
  for (size_t i = 0; i < sorted.size(); ++i) *sorted[i].first = said[i];
}

class Parser {
 public:
  Parser(const std::string& text, const Vocabulary& vocabulary, size_t from = 0, size_t to = std::string::npos,
         bool prefix = false)
      : Parser(text, vocabulary, TokenView{}, prefix) {
    owned_ = readableWords(tokenize(text, from, std::min(to, text.size())), vocabulary);
    tokens_ = TokenView{owned_.data(), owned_.size()};
  }
  // Over tokens of `text` tokenised elsewhere (NounPhraseReader): `tokens` must outlive the parser.
  Parser(const std::string& text, const Vocabulary& vocabulary, TokenView tokens, bool prefix)
      : text_(text),
        v_(vocabulary),
        tokens_(tokens),
        prefix_(prefix),
        intensityWords_(vocabulary.intensityWords()),
        adjectiveWords_(vocabulary.adjectiveWords()),
        nounWords_(vocabulary.nounWords()),
        directionWords_(vocabulary.directionWords()),
        distanceWords_(vocabulary.distanceWords()) {}

  // Errors name no corrected text (didYouMean): for trials and for asking whether a text reads.
  void noSuggestions() { suggest_ = false; }

  LinguisticQuery parse() {
    entry_ = Entry::kQuery;
    LinguisticQuery q;
    if (tokens_.empty()) fail({"a query such as 'find a slightly bent shape'"});
    skipRequest();
    const size_t start = pos_;
    std::string subject;
    QueryCondition first = nounPhrase(&subject);
    q.subject = subject;
    if (startsRelation()) {
      QueryCondition relation;
      relation.kind = Kind::kRelation;
      relation.distance = optionalDistance();
      relation.directionSets = directionPhrase();
      relation.direction = relation.directionSets->word;
      std::string otherSubject;
      QueryCondition other = nounPhrase(&otherSubject);
      relation.children = {std::move(first), std::move(other)};
      relation.text = span(start, pos_);
      q.root = std::move(relation);
      q.subject = "shape";
    } else {
      q.root = std::move(first);
    }
    if (acceptWord("with")) {
      expectWord("score");
      if (!at("at")) fail({"'at least' NUMBER"});
    }
    if (at("at")) {
      ++pos_;
      expectWord("least");
      if (pos_ >= tokens_.size() || !tokens_[pos_].number) fail({"a number in [0, 1] (the least score)"});
      const double threshold = std::strtod(tokens_[pos_].text.c_str(), nullptr);
      if (threshold < 0.0 || threshold > 1.0)
        throw Error(errc::kInvalidParameter,
                    "the least score at character " + std::to_string(tokens_[pos_].offset) + " must be in [0, 1]",
                    "text");
      q.atLeast = threshold;
      ++pos_;
    }
    // aggregation = "using" ( "min" | "product" | "mean" ): how "and" combines scores
    if (acceptWord("using")) {
      if (pos_ >= tokens_.size() || !v_.isAggregation(tokens_[pos_].text))
        fail({"an aggregation (" + joinList(v_.aggregationNames()) + ")"});
      q.aggregation = tokens_[pos_++].text;
    }
    if (pos_ < tokens_.size())
      fail({"'and'", "'or'", "'that is'", "'at least' NUMBER", "'using' AGGREGATION",
            "a distance and a direction (" + joinList(directionWords_) + ")", "the end of the query"});
    return q;
  }

  // A noun phrase at the start of the tokens, ending where the phrase ends (parseNounPhraseAt).
  NounPhraseAt nounPhraseAt() {
    NounPhraseAt out;
    if (tokens_.empty()) fail({"a noun phrase such as 'a slightly bent cylinder'"});
    std::string subject;
    out.query.root = nounPhrase(&subject);
    out.query.subject = subject;
    out.end = tokens_[pos_ - 1].end;
    return out;
  }

  // part_description = [ article ] adjectives noun { measure } [ [ "," ] adjectives ]
  //                    [ "with" ( edge | measure { [ "," | "and" ] measure } ) ]
  PartDescription partDescription() {
    entry_ = Entry::kPartDescription;
    PartDescription d;
    if (tokens_.empty()) fail({"words such as 'a slightly bent cylinder'"});
    // A request before the words, as a query has one ("find a box", "show me ..."): the same words
    // make the part that the query finds (the search box's typical first, typical_first.h).
    skipRequest();
    const bool indefinite = at("a") || at("an");
    acceptAny(queryArticles());
    std::string word;
    // "a 4 cube": the noun's longest extent, as a query reads it (nounPhrase).
    if (std::optional<QueryCondition> size = sizeBeforeNoun(indefinite))
      d.measures.push_back({size->descriptor, *size->measure, size->text});
    adjectiveUses(&d);
    const size_t n = matchPhrase(nounWords_, &word);
    if (n == 0) {
      std::vector<std::string> expected = {"a noun (" + joinList(nounWords_) + ")"};
      if (d.adjectives.empty()) {
        const std::vector<std::string> starts = conditionStarts();  // 'not', '(', intensity, adjective
        expected.insert(expected.begin(), starts.begin() + 2, starts.begin() + 4);
      }
      fail(expected);
    }
    pos_ += n;
    d.noun = v_.noun(word);
    // A plain adjective that names a noun's shape, on a noun with no shape of its own, is that
    // noun, as in a query ("a cylindrical thing" is a cylinder).
    if (d.noun->params.is_null())
      for (auto use = d.adjectives.begin(); use != d.adjectives.end(); ++use)
        if (!use->intensity && !use->adjective->shapeOf.empty()) {
          d.noun = v_.noun(use->adjective->shapeOf);
          d.adjectives.erase(use);
          break;
        }
    partNoun_ = d.noun;
    const auto addMeasures = [&d](std::vector<QueryCondition> measures) {
      for (QueryCondition& m : measures) {
        std::vector<QueryCondition> leaves;
        if (m.kind == Kind::kDescriptor) leaves.push_back(std::move(m));
        else leaves = std::move(m.children);
        for (const QueryCondition& leaf : leaves) d.measures.push_back({leaf.descriptor, *leaf.measure, leaf.text});
      }
    };
    addMeasures(measuresAfterNoun());
    // Adjectives after the noun, as a query reads them ("a cylinder slightly bent", "a box, very
    // twisted"): the same as before it.
    {
      const size_t beforeComma = pos_;
      const bool comma = acceptWord(",");
      if (adjectiveUses(&d) == 0 && comma) pos_ = beforeComma;
    }
    // [ "with" edge ] ("a cube with rounded edges", "a cylinder with sharp edges"); or an
    // edges.before_nouns adjective of a noun with a squariness condition, plain or with an
    // intensity, says its edges ("a rounded box", "a somewhat softened box"), as in a query.
    // Or measures after "with", as a query reads them ("a cylinder with diameter 2 and length 1").
    if (at("with")) {
      const size_t start = ++pos_;
      const Adjective* featured = nullptr;
      const FuzzyNumber* featureIntensity = nullptr;
      if (startsMeasure()) {
        addMeasures(measuresAfterNoun());
      } else if (const size_t k = featurePhraseLength(&featured, &featureIntensity)) {
        // "a cylinder with a slight bend": the adjective the noun stands for, with its degree.
        pos_ += k;
        d.adjectives.push_back({featured, featureIntensity, span(start, pos_)});
      } else {
        std::optional<FuzzyNumber> degree = edgePhrase();
        if (!degree)
          fail({"the shape of its edges ('with rounded edges', 'with sharp edges')",
                "a measure ('with diameter 2 and length 1')"});
        d.edges = EdgeUse{std::move(*degree), span(start, pos_)};
      }
    }
    if (isSquareNoun(*d.noun))
      for (auto use = d.adjectives.begin(); use != d.adjectives.end(); ++use)
        if (v_.saysEdgesBeforeNouns(use->adjective->word)) {
          // With an intensity, its set as the edges' degree, as a query reads it (negation()).
          const FuzzyNumber degree = !use->intensity           ? v_.edgeSet()
                                     : use->adjective->lowPole ? mirroredDegrees(*use->intensity)
                                                               : *use->intensity;
          if (!d.edges) d.edges = EdgeUse{degree, use->text};  // the words after the noun win
          d.adjectives.erase(use);
          break;
        }
    if (pos_ < tokens_.size())
      fail({"the end of the description (a part is adjectives, one noun and its measures: 'a pole about 10 long')"});
    // The measures as the same words read as a query read them: a length along the axis of a noun
    // turned about z, and contradicting roles sorted.
    std::vector<std::pair<std::string*, const FuzzyNumber*>> measures;
    for (MeasureUse& m : d.measures) {
      if (m.descriptor == "length" && axial(*d.noun)) m.descriptor = "height";
      measures.push_back({&m.descriptor, &m.extent});
    }
    sortMeasuredRoles(measures);
    // The noun's conditions that the words keep, as the same words read as a query keep them: a
    // plain adjective on one of their descriptors takes a degree where both are highest.
    std::vector<QueryCondition> said;
    for (const AdjectiveUse& use : d.adjectives) {
      QueryCondition c = descriptorCondition(v_.descriptorOn(*use.adjective, d.noun),
                                             use.intensity ? *use.intensity : v_.plainSet(*use.adjective), use.text);
      c.plainRamp = !use.intensity && !use.adjective->set;
      // A proportion the words say is kept as the noun's is: one extent asked for scales the part
      // ("a short thick cylinder" is a short cylinder made thick; thickening its section alone
      // left it long).
      d.keepsProportions = d.keepsProportions || isProportion(c.descriptor);
      said.push_back(std::move(c));
    }
    for (const MeasureUse& m : d.measures) {
      QueryCondition c = descriptorCondition(m.descriptor, m.extent, m.text);
      c.measure = m.extent;
      said.push_back(std::move(c));
    }
    if (d.edges) {
      QueryCondition c = descriptorCondition("squariness", d.edges->degree, d.edges->text);
      c.edges = QueryCondition::Edges::kNamed;
      said.push_back(std::move(c));
    }
    std::vector<const QueryCondition*> saidLeaves;
    for (const QueryCondition& c : said) saidLeaves.push_back(&c);
    const auto graded = [](const QueryCondition& c) { return !c.plainRamp; };
    for (const NounCondition& n : d.noun->conditions) {
      if (overriddenByWords(n, *d.noun, saidLeaves, graded)) continue;
      d.keepsProportions = d.keepsProportions || isProportion(n.descriptor);
      for (size_t i = 0; i < d.adjectives.size(); ++i)
        if (said[i].plainRamp && said[i].descriptor == n.descriptor && !d.adjectives[i].nounSet)
          d.adjectives[i].nounSet = n.set;
    }
    return d;
  }

 private:
  // --- tokens ---------------------------------------------------------------------------------
  bool at(const std::string& w) const { return pos_ < tokens_.size() && tokens_[pos_].text == w; }
  bool acceptWord(const std::string& w) {
    if (!at(w)) return false;
    ++pos_;
    return true;
  }
  bool acceptAny(const std::vector<std::string>& words) {
    for (const std::string& w : words)
      if (acceptWord(w)) return true;
    return false;
  }
  void expectWord(const std::string& w) {
    if (!acceptWord(w)) fail({"'" + w + "'"});
  }

  // request = the longest request phrase of the vocabulary ("show me", "I am looking for") or verb,
  // a verb with an optional "for". Nothing of it is part of the query.
  void skipRequest() {
    pos_ += requestLength(
        [this](size_t k) { return pos_ + k < tokens_.size() ? &tokens_[pos_ + k].text : nullptr; }, v_);
  }

  // The longest phrase of `phrases` (words separated by one space) starting at the current
  // token: the number of tokens it spans (0: none) and the phrase.
  size_t matchPhrase(const std::vector<std::string>& phrases, std::string* matched, size_t skip = 0) const {
    const size_t from = pos_ + skip;  // `skip` tokens ahead of the current one
    const auto wordAt = [this, from](size_t k) { return from + k < tokens_.size() ? &tokens_[from + k].text : nullptr; };
    size_t best = 0;
    for (const std::string& phrase : phrases) {
      const size_t k = query_tokens::phraseLength(wordAt, phrase);
      if (k > best) {
        best = k;
        *matched = phrase;
      }
    }
    return best;
  }

  std::string span(size_t from, size_t to) const {
    if (to <= from) return "";
    return text_.substr(tokens_[from].offset, tokens_[to - 1].end - tokens_[from].offset);
  }

  bool knows(const std::string& word) const { return knowsLinguisticWord(word, v_); }

  [[noreturn]] void fail(const std::vector<std::string>& expected) const {
    if (pos_ >= tokens_.size())
      throw Error(errc::kInvalidParameter,
                  "the query ends too early (character " + std::to_string(text_.size()) +
                      "); expected " + joinList(expected),
                  "text");
    const Token& t = tokens_[pos_];
    if (!t.number && t.text.size() > 1 && std::isalpha(static_cast<unsigned char>(t.text[0])) && !knows(t.text)) {
      std::vector<std::string> known(v_.words().begin(), v_.words().end());
      known.insert(known.end(), grammarWords().begin(), grammarWords().end());
      known.insert(known.end(), descriptorNames().begin(), descriptorNames().end());
      known.insert(known.end(), measureWords().begin(), measureWords().end());
      throw Error(errc::kInvalidParameter,
                  "unknown word '" + quotedWord(t.text) + "' at character " + std::to_string(t.offset) + "; closest known words: " +
                      closestNames(t.text, known) + didYouMean(t, known),
                  "text");
    }
    throw Error(errc::kInvalidParameter,
                "unexpected '" + quotedWord(t.text) + "' at character " + std::to_string(t.offset) + "; expected " + joinList(expected),
                "text");
  }

  // "; did you mean \"...\"?": the text with the unknown word t replaced by the nearest known word
  // (of the five nearest) with which the whole text reads, or "" when none does. Only for whole
  // texts (queries and part descriptions), and not again inside such a trial; not for a word no
  // known word is within kEditDistanceLimit edits of, nor for a text too long to quote back.
  std::string didYouMean(const Token& t, const std::vector<std::string>& known) const {
    if (prefix_ || !suggest_ || text_.size() > kLongestSuggestedText) return "";
    std::vector<std::pair<size_t, std::string>> nearest;
    for (const std::string& k : known) nearest.emplace_back(editDistance(t.text, k), k);
    std::sort(nearest.begin(), nearest.end());
    nearest.erase(std::unique(nearest.begin(), nearest.end()), nearest.end());
    for (size_t i = 0; i < nearest.size() && i < 5 && nearest[i].first <= kEditDistanceLimit; ++i) {
      const std::string trial = text_.substr(0, t.offset) + nearest[i].second + text_.substr(t.end);
      try {
        Parser parser(trial, v_);
        parser.noSuggestions();
        if (entry_ == Entry::kQuery) parser.parse();
        else parser.partDescription();
        return "; did you mean \"" + trial + "\"?";
      } catch (const Error&) {
      }
    }
    return "";
  }

  // --- productions ----------------------------------------------------------------------------
  // Accepts `w` joining two conditions. In a noun phrase read as a prefix (nounPhraseAt), a `w`
  // not followed by the start of a condition ends the phrase instead: it joins the next operand
  // of the caller ("the union of a cylinder that is bent and a cube").
  bool continues(const std::string& w) {
    if (!at(w)) return false;
    ++pos_;
    if (prefix_ && !startsCondition()) {
      --pos_;
      return false;
    }
    return true;
  }

  bool startsCondition() const {
    if (at("not") || at("(") || startsArticleSection() || startsMeasure() || taperPhraseLength(nullptr) > 0 ||
        featurePhraseLength(nullptr, nullptr) > 0)
      return true;
    if (pos_ < tokens_.size() && descriptorIndex(tokens_[pos_].text) >= 0) return true;
    std::string m;
    return matchPhrase(intensityWords_, &m) > 0 || matchPhrase(adjectiveWords_, &m) > 0;
  }

  std::vector<std::string> conditionStarts() const {
    return {"'not'", "'('", "an intensity (" + joinList(intensityWords_) + ")",
            "an adjective (" + joinList(adjectiveWords_) + ")",
            "a descriptor and its degree (" + joinList(descriptorNames()) + ")",
            "a measure ('about 10 long', '2 across', 'diameter 2')"};
  }

  // --- measures (see the header) ----------------------------------------------------------------
  // The tokens a number phrase spans at token `at` (0: none).
  size_t numberPhraseTokens(size_t at) const {
    if (at >= tokens_.size()) return 0;
    if (tokens_[at].number) return 1;
    if (contains(kApproximately, tokens_[at].text)) return at + 1 < tokens_.size() && tokens_[at + 1].number ? 2 : 0;
    if (tokens_[at].text == "between")
      return at + 3 < tokens_.size() && tokens_[at + 1].number && tokens_[at + 2].text == "and" && tokens_[at + 3].number
                 ? 4
                 : 0;
    return 0;
  }

  bool isWordAt(size_t at, std::initializer_list<const char*> words) const {
    if (at >= tokens_.size()) return false;
    for (const char* w : words)
      if (tokens_[at].text == w) return true;
    return false;
  }

  // Whether a measure starts at the current token: number_phrase [ "unit(s)" ] dimension word,
  // number_phrase ( "x" | "by" ) NUMBER ..., or [ "of" ] [ article ] dimension noun [ "of" | "is" ]
  // number_phrase.
  bool startsMeasure() const {
    static const std::vector<std::string> after = phrasesOf(dimensionsAfterNumber());
    static const std::vector<std::string> before = phrasesOf(dimensionsBeforeNumber());
    std::string m;
    size_t at = pos_;
    // "of" before a number ("a rod of 6 length") only where a dimension follows the number; an
    // article only before the numbers of a section ("with a 0.6 by 1 cross section", "with a 0.5
    // section").
    if (isWordAt(at, {"a", "an", "its"}) && numberPhraseTokens(at + 1)) {
      const size_t n = numberPhraseTokens(at + 1);
      if (isWordAt(at + 1 + n, {"x", "by"})) return at + 2 + n < tokens_.size() && tokens_[at + 2 + n].number;
      size_t after = at + 1 + n;
      if (isWordAt(after, {"unit", "units"})) ++after;
      static const std::vector<std::string> afterWords = phrasesOf(dimensionsAfterNumber());
      return matchPhrase(afterWords, &m, after - pos_) > 0 &&
             dimensionWord(dimensionsAfterNumber(), m).descriptor == "section";
    }
    const size_t number = isWordAt(at, {"of"}) ? at + 1 : at;
    if (const size_t n = numberPhraseTokens(number)) {
      at = number + n;
      if (isWordAt(at, {"x", "by"}) && at + 1 < tokens_.size() && tokens_[at + 1].number) return true;
      if (isWordAt(at, {"unit", "units"})) ++at;
      if (isWordAt(at, {"base", "footprint"}) && matchPhrase(after, &m, at + 1 - pos_) > 0) ++at;
      return matchPhrase(after, &m, at - pos_) > 0;
    }
    if (isWordAt(at, {"of"})) ++at;
    if (isWordAt(at, {"a", "an", "the", "its"})) ++at;
    const size_t k = matchPhrase(before, &m, at - pos_);
    if (k == 0) return false;
    at += k;
    if (dimensionWord(dimensionsBeforeNumber(), m).descriptor == "base") {
      std::string measured;  // "base diameter 2"
      if (const size_t j = matchPhrase(before, &measured, at - pos_);
          j > 0 && dimensionWord(dimensionsBeforeNumber(), measured).descriptor != "base")
        at += j;
    }
    if (isWordAt(at, {"of", "is"})) ++at;
    return numberPhraseTokens(at) > 0;
  }

  // A measure's number: a plain N is within 10 % of N (tri(0.9 N, N, 1.1 N)), any other number
  // phrase as written; the extent must be positive.
  FuzzyNumber measureNumber() {
    const size_t start = pos_;
    std::optional<FuzzyNumber> n = numberPhrase("measure");
    if (!n) fail({"a number"});
    const bool positive = n->core().lo > 0.0;
    if (pos_ == start + 1 && positive) {
      const double x = n->core().lo;
      n = FuzzyNumber::triangular(0.9 * x, x, 1.1 * x);
    }
    if (!positive)
      throw Error(errc::kInvalidParameter,
                  "a measure is a positive extent; the one at character " + std::to_string(tokens_[start].offset) +
                      " is not",
                  "text");
    return *n;
  }

  void acceptUnits() {
    if (!acceptWord("units")) acceptWord("unit");
  }

  void addMeasure(const DimensionWord& d, const FuzzyNumber& number, const std::string& text,
                  std::vector<QueryCondition>* out) const {
    if (!std::isfinite(number.support().hi * d.factor))
      throw Error(errc::kInvalidParameter, "the measure '" + text + "' is too large for a number", "text");
    const FuzzyNumber extent = d.factor == 1.0 ? number : scale(number, d.factor);
    if (d.descriptor == "cube") {
      for (const char* descriptor : {"thickness", "width", "length"}) out->push_back(measureCondition(descriptor, extent, text));
    } else if (d.descriptor == "section") {
      for (const char* descriptor : {"thickness", "width"}) out->push_back(measureCondition(descriptor, extent, text));
    } else {
      out->push_back(measureCondition(d.descriptor, extent, text));
    }
  }

  // A base of sides `a` and `b` read from token `start` (its units, if said, next): its width
  // (widthOfBase), its sides kept in lastBase_ for measuresAfterNoun to sort with a height.
  QueryCondition baseMeasure(const FuzzyNumber& a, const FuzzyNumber& b, size_t start, std::vector<QueryCondition>* out) {
    acceptUnits();
    lastBase_ = std::make_pair(a, b);
    out->push_back(measureCondition("width", widthOfBase(a, b), span(start, pos_)));
    return group(Kind::kAnd, std::move(*out), start);
  }

  // measure, at startsMeasure(): one condition, or an "and" of them (three sides, a side).
  QueryCondition measure() {
    static const std::vector<std::string> after = phrasesOf(dimensionsAfterNumber());
    static const std::vector<std::string> before = phrasesOf(dimensionsBeforeNumber());
    const size_t start = pos_;
    std::vector<QueryCondition> out;
    std::string word;
    if ((at("of") || at("a") || at("an") || at("its")) && numberPhraseTokens(pos_ + 1)) ++pos_;
    if (numberPhraseTokens(pos_)) {
      const FuzzyNumber first = measureNumber();
      if (at("x") || at("by")) {
        // "4 x 2 x 1": the three extents, sorted: the shortest is the thickness, the longest the
        // length. "0.6 by 1 cross section": the two shorter, the section across the length.
        std::vector<FuzzyNumber> sides{first};
        while ((at("x") || at("by")) && sides.size() < 3) {
          ++pos_;
          sides.push_back(measureNumber());
        }
        acceptUnits();
        std::string section;
        if (sides.size() == 2) {
          const size_t n = matchPhrase(sectionWords(), &section);
          if (n == 0)
            fail({"'x' and a third number (the three sides of a box: '4 x 2 x 1')",
                  "a section word after two numbers ('0.6 by 1 cross section')"});
          pos_ += n;
          if (section == "base" || section == "footprint") {
            // "a 1 x 1 base": its width (widthOfBase); with a height beside it, measuresAfterNoun
            // sorts the three.
            return baseMeasure(sides[0], sides[1], start, &out);
          }
        }
        std::stable_sort(sides.begin(), sides.end(), shorterExtent);
        const char* names[] = {"thickness", "width", "length"};
        for (size_t i = 0; i < sides.size(); ++i) out.push_back(measureCondition(names[i], sides[i], span(start, pos_)));
      } else {
        acceptUnits();
        // "2 base diameter": the dimension at the base, as "base diameter 2".
        if ((at("base") || at("footprint")) && matchPhrase(after, &word, 1) > 0) ++pos_;
        const size_t n = matchPhrase(after, &word);
        if (n == 0) fail({"a dimension word (" + joinList(after) + ")"});
        pos_ += n;
        addMeasure(dimensionWord(dimensionsAfterNumber(), word), first, span(start, pos_), &out);
      }
    } else {
      acceptWord("of");
      acceptAny({"a", "an", "the", "its"});
      size_t n = matchPhrase(before, &word);
      if (n == 0) fail({"a dimension (" + joinList(before) + ")"});
      pos_ += n;
      // "base diameter 2", "base width 3": the dimension at the base.
      if (dimensionWord(dimensionsBeforeNumber(), word).descriptor == "base") {
        std::string measured;
        if ((n = matchPhrase(before, &measured)) > 0 && dimensionWord(dimensionsBeforeNumber(), measured).descriptor != "base") {
          pos_ += n;
          word = measured;
        }
      }
      if (!acceptWord("of")) acceptWord("is");
      const FuzzyNumber number = measureNumber();
      if (dimensionWord(dimensionsBeforeNumber(), word).descriptor == "base") {
        // "base 2 x 2": the width between its sides (widthOfBase); "base 2": the width.
        if (at("x") || at("by")) {
          ++pos_;
          const FuzzyNumber second = measureNumber();
          return baseMeasure(number, second, start, &out);
        }
        acceptUnits();
        out.push_back(measureCondition("width", number, span(start, pos_)));
        return group(Kind::kAnd, std::move(out), start);
      }
      acceptUnits();
      addMeasure(dimensionWord(dimensionsBeforeNumber(), word), number, span(start, pos_), &out);
    }
    return group(Kind::kAnd, std::move(out), start);
  }

  // Measures right after a noun: [ "," ] measure { ( "," | "and" ) measure }; a joining word not
  // followed by a measure is left for what comes next.
  // A base said beside a height ("a wedge, base 2 x 2, height 1"): the three are the part's
  // extents, sorted as three sides are, so that a flat part's base is its two longer sides.
  // Without a height the base says its width alone (widthOfBase).
  std::vector<QueryCondition> measuresAfterNoun() {
    std::vector<QueryCondition> out;
    std::optional<size_t> baseAt;
    std::optional<std::pair<FuzzyNumber, FuzzyNumber>> base;
    std::optional<FuzzyNumber> height;
    const auto finish = [&]() {
      if (!baseAt || !height) return;  // a base alone is its width (measure())
      if (entry_ == Entry::kPartDescription) {
        // A part made from words: a height names the z axis, and the roles said beside it go to
        // the other two, the shorter to the shorter (realizeExtents): the base's sides.
        QueryCondition& group = out[*baseAt];
        const std::string text = group.text;
        // A square base of a noun whose two axes across z are alike (a pyramid, a box, not a
        // wedge, tapered along one): one role, which the other axis, as long, follows with the
        // same spread, so the part's sides are the same fuzzy number and its words score it 1.
        const auto taper = [&](const char* k) {
          return partNoun_ && partNoun_->params.is_object() ? partNoun_->params.value(k, 0.0) : 0.0;
        };
        if (base->first == base->second && taper("kx") == taper("ky")) {
          group = measureCondition("width", base->first, text);  // not length: a cone's is its height
          return;
        }
        const bool swap = shorterExtent(base->second, base->first);
        const FuzzyNumber& shorter = swap ? base->second : base->first;
        const FuzzyNumber& longer = swap ? base->first : base->second;
        group.kind = Kind::kAnd;
        group.children = {measureCondition("thickness", shorter, text), measureCondition("length", longer, text)};
        return;
      }
      std::vector<FuzzyNumber> sides = {base->first, base->second, *height};
      std::stable_sort(sides.begin(), sides.end(), shorterExtent);
      QueryCondition& group = out[*baseAt];
      const std::string text = group.kind == Kind::kAnd && !group.children.empty() ? group.children[0].text : group.text;
      std::vector<QueryCondition> three;
      const char* names[] = {"thickness", "width", "length"};
      for (size_t i = 0; i < 3; ++i) three.push_back(measureCondition(names[i], sides[i], text));
      group.kind = Kind::kAnd;
      group.children = std::move(three);
    };
    while (true) {
      const size_t save = pos_;
      if (!acceptWord(",") && !out.empty()) acceptWord("and");
      if (!startsMeasure()) {
        pos_ = save;
        finish();
        return out;
      }
      lastBase_.reset();
      out.push_back(measure());
      if (lastBase_ && !baseAt) {
        baseAt = out.size() - 1;
        base = lastBase_;
      }
      const QueryCondition& m = out.back();
      const auto holdsHeight = [](const QueryCondition& c) { return c.kind == Kind::kDescriptor && c.descriptor == "height"; };
      if (holdsHeight(m)) height = *m.measure;
      for (const QueryCondition& c : m.children)
        if (holdsHeight(c)) height = *c.measure;
    }
  }

  // The noun named by a plain adjective of `parts` that names a noun's shape (Adjective::shapeOf:
  // "cylindrical"), taken out of them with its text; null when none is. Only a leaf said by
  // itself or in an "and" of leaves: under "not" or "or" the word says something else.
  const Noun* takeShapeNoun(std::vector<QueryCondition>* parts, std::string* text) const {
    const auto names = [&](const QueryCondition& c) -> const Noun* {
      if (c.kind != Kind::kDescriptor || c.measure || c.edges != QueryCondition::Edges::kNone) return nullptr;
      const Adjective* a = v_.adjective(c.text);
      return a && !a->shapeOf.empty() && c.descriptor == a->descriptor ? v_.noun(a->shapeOf) : nullptr;
    };
    for (auto part = parts->begin(); part != parts->end(); ++part) {
      if (const Noun* noun = names(*part)) {
        *text = part->text;
        parts->erase(part);
        return noun;
      }
      if (part->kind != Kind::kAnd) continue;
      for (auto child = part->children.begin(); child != part->children.end(); ++child)
        if (const Noun* noun = names(*child)) {
          *text = child->text;
          part->children.erase(child);
          if (part->children.size() == 1) {
            QueryCondition only = std::move(part->children[0]);
            *part = std::move(only);
          }
          return noun;
        }
    }
    return nullptr;
  }

  // A size said before its noun, after "a" or "an" (`indefinite`): a number phrase and
  // "unit(s)" if said, with a noun next. Read as the noun's longest extent (a cube's side, a
  // ball's diameter, a rod's length); nullopt, reading nothing, where no such size is there.
  std::optional<QueryCondition> sizeBeforeNoun(bool indefinite) {
    if (!indefinite) return std::nullopt;
    size_t k = pos_ + numberPhraseTokens(pos_);
    if (k == pos_) return std::nullopt;
    if (isWordAt(k, {"unit", "units"})) ++k;
    std::string word;
    if (matchPhrase(nounWords_, &word, k - pos_) == 0) return std::nullopt;
    const size_t numberStart = pos_;
    const FuzzyNumber extent = measureNumber();
    acceptUnits();
    return measureCondition("length", extent, span(numberStart, pos_) + " (its longest extent)");
  }

  // noun_phrase = [ article ] [ number_phrase [ "unit(s)" ] | condition ] noun
  //               [ ("that"|"which") ("is"|"are") condition ]
  QueryCondition nounPhrase(std::string* subject) {
    const size_t start = pos_;
    const bool indefinite = at("a") || at("an");
    const bool article = acceptAny(queryArticles());
    std::vector<QueryCondition> parts;
    // An engineer's size before the noun: "a 4 cube", "a 2 unit ball", "an 0.8 rod" give the
    // noun's longest extent (the side of a cube, a ball's diameter, a rod's length); after "a" a
    // number is no count.
    if (std::optional<QueryCondition> size = sizeBeforeNoun(indefinite)) parts.push_back(std::move(*size));
    const bool hasModifiers = parts.empty() && startsCondition();
    if (hasModifiers) parts.push_back(condition());
    std::string word;
    const size_t nounStart = pos_;
    const size_t n = matchPhrase(nounWords_, &word);
    // An adjective that names a noun's shape, with no noun after it ("cylindrical", "a part that
    // is ..." aside) or before a noun with no shape of its own ("a cylindrical thing", "something
    // conical"), is that noun: a ball has a round section, but it is not cylindrical.
    std::string shapeText;
    const Noun* shaped = nullptr;
    if (n == 0 && hasModifiers && !prefix_) shaped = takeShapeNoun(&parts, &shapeText);
    if (n == 0 && hasModifiers && !article && !prefix_ && !shaped) {
      // A bare description ("slightly bent", "round and tapered") is a query about any shape. With
      // an article ("a slightly bent") the noun is still expected: the phrase is unfinished. It
      // may take a "with" clause as a noun does: "very sharp with squarish traverse section"
      // (Zhang, Pham & Chen, §1), read as "a very sharp shape with squarish traverse section".
      *subject = "any";
      if (at("with") && !(pos_ + 1 < tokens_.size() && tokens_[pos_ + 1].text == "score")) {
        ++pos_;
        if (!startsCondition()) fail(conditionStarts());
        parts.push_back(condition());
        QueryCondition all;
        all.kind = Kind::kAnd;
        all.nounPhrase = true;
        all.children = std::move(parts);
        return all;
      }
      return std::move(parts[0]);
    }
    if (n == 0 && !shaped) {
      std::vector<std::string> expected;
      if (!hasModifiers) expected = conditionStarts();
      expected.push_back("a noun (" + joinList(nounWords_) + ")");
      fail(expected);
    }
    pos_ += n;
    const Noun* named = shaped ? shaped : v_.noun(word);
    *subject = shaped ? "any" : named->subject;
    // "something twisted": a pronoun takes its adjectives after it.
    if (named->pronoun && !hasModifiers && startsCondition()) parts.push_back(condition());
    const bool shapeless = !shaped && named->params.is_null() && named->conditions.empty();
    if (shapeless) shaped = takeShapeNoun(&parts, &shapeText);  // "a cylindrical thing", "something conical"
    // Words said after the noun they name (a bare description, a pronoun's adjectives): what is
    // left of them is the noun's clause, as "shapes that are conical and small" reads.
    const bool wordsAfter = n == 0 || (named->pronoun && !hasModifiers);
    size_t nounAt = parts.size();
    std::string nounText = shaped ? shapeText : span(nounStart, pos_);
    // Measures right after the noun ("a rod 6 long and 0.2 across") join its clause, if any: one
    // condition after the noun, as "that is" gives.
    const size_t clauseStart = pos_;
    std::vector<QueryCondition> clause = measuresAfterNoun();
    // Adjectives after the noun, as many speakers put them ("ball small", "cylinder very long
    // thin", "box long and flat"), or after a comma ("a box, very twisted"): read as a clause, "a
    // ball that is small".
    if (startsCondition()) {
      clause.push_back(condition());
    } else if (at(",") && !prefix_) {
      // Not in a list of operands, where a comma is the caller's ("the union of a cube, (a
      // sphere ...)", "..., a round cross-section cone"); not before "(" or an article either.
      ++pos_;
      if (startsCondition() && !at("(") && !startsArticleSection())
        clause.push_back(condition());
      else
        --pos_;
    }
    const size_t beforeRelative = pos_;
    // A comma may set the relative clause off: "a cylinder, slightly bent, with a round cross-section".
    const auto wordAfter = [&](size_t k) { return pos_ + k < tokens_.size() ? tokens_[pos_ + k].text : std::string(); };
    if (at(",") && (wordAfter(1) == "that" || wordAfter(1) == "which" || (wordAfter(1) == "with" && wordAfter(2) != "score")))
      ++pos_;
    if (acceptWord("that") || acceptWord("which")) {
      const bool verb = acceptAny({"is", "are", "has", "have"});
      if ((verb || taperPhraseLength(nullptr) > 0) && startsCondition()) {  // "that gets thinner at the top"
        clause.push_back(condition());
      } else if (prefix_) {
        // Read as a prefix (a CSG operand), a relative clause that states no condition ends the
        // phrase: the caller reads it ("three balls which are glued in line").
        pos_ = beforeRelative;
      } else {
        if (!verb) fail({"'is'", "'are'", "'has'", "'have'"});
        fail(conditionStarts());
      }
    } else if (at("of") && startsSectionAfterOf()) {
      // "a bar of square section", "a rod of a round cross-section": the section as "with" says it.
      ++pos_;
      clause.push_back(condition());
    } else if (at("with") && !(pos_ + 1 < tokens_.size() && tokens_[pos_ + 1].text == "score")) {
      ++pos_;
      if (!startsCondition()) {
        // Read as a prefix (a CSG operand), "with" before no condition ends the phrase: it joins
        // the caller's next operand ("a cube with a sphere", "a cube with a cylindrical hole").
        if (!prefix_) fail(conditionStarts());
        pos_ = beforeRelative;
      } else {
        clause.push_back(condition());
      }
    }
    // Or in its clause: "a part that is cylindrical".
    if (shapeless && !shaped && (shaped = takeShapeNoun(&clause, &shapeText))) nounText = shapeText;
    if (shaped && wordsAfter && !parts.empty()) {
      clause.insert(clause.begin(), std::make_move_iterator(parts.begin()), std::make_move_iterator(parts.end()));
      parts.clear();
      nounAt = 0;
    }
    if (shaped) named = shaped;
    const Noun& noun = *named;
    // Outline adjectives describe a flat noun's outline, its traverse section ("a round plate",
    // "a plate that is not square"); elsewhere they keep their descriptor.
    for (std::vector<QueryCondition>* said : {&parts, &clause})
      for (QueryCondition& c : *said) {
        turnOutlines(&c, noun);
        turnEdges(&c, noun);
        turnAxialLength(&c, noun);
      }
    {
      std::vector<std::pair<std::string*, const FuzzyNumber*>> measures;
      const std::function<void(QueryCondition&)> collect = [&](QueryCondition& c) {
        if (c.kind == Kind::kDescriptor && c.measure) measures.push_back({&c.descriptor, &*c.measure});
        if (c.kind == Kind::kAnd)
          for (QueryCondition& child : c.children) collect(child);
      };
      for (std::vector<QueryCondition>* said : {&parts, &clause})
        for (QueryCondition& c : *said) collect(c);
      sortMeasuredRoles(measures);
    }
    if (!noun.conditions.empty()) {
      // Nouns are defaults: a condition the words state themselves may replace the noun's on the
      // same quality (overriddenByWords): "a round plate" is round, not square.
      std::vector<const QueryCondition*> said;
      for (const QueryCondition& c : parts) collectLeaves(c, &said);
      for (const QueryCondition& c : clause) collectLeaves(c, &said);
      std::vector<QueryCondition> leaves;
      const auto graded = [&](const QueryCondition& c) { return !c.plainRamp; };
      // A flat noun whose outline the words set ("a round plate", "a square disc") keeps its
      // profile: its flat faces and sharp rims, which its exponent shape said beside its own outline.
      const std::vector<QueryCondition> profile = profileConditions(noun, said, graded, nounText);
      leaves.insert(leaves.end(), profile.begin(), profile.end());
      for (const NounCondition& c : noun.conditions)
        if (!overriddenByWords(c, noun, said, graded)) {
          leaves.push_back(descriptorCondition(c.descriptor, c.set, nounText + ": " + c.descriptor));
          // A plain word the noun's condition caps: both score relative to what they allow together.
          for (std::vector<QueryCondition>* words : {&parts, &clause})
            for (QueryCondition& w : *words) relateToNoun(&w, &leaves.back());
        }
      QueryCondition node;
      if (leaves.size() == 1) {
        node = std::move(leaves[0]);
      } else {
        node.kind = Kind::kAnd;  // none left: the noun says nothing more ("anything")
        node.children = std::move(leaves);
      }
      node.text = nounText;
      node.noun = noun.word;
      parts.insert(parts.begin() + static_cast<std::ptrdiff_t>(nounAt), std::move(node));
    }
    if (!clause.empty()) parts.push_back(group(Kind::kAnd, std::move(clause), clauseStart));
    if (parts.size() == 1) return std::move(parts[0]);
    QueryCondition all;  // empty: "anything" (a bare "shape")
    all.kind = Kind::kAnd;
    all.nounPhrase = true;
    all.children = std::move(parts);
    if (all.children.empty()) all.text = span(start, pos_);
    return all;
  }

  // condition = conjunct { "or" conjunct }
  QueryCondition condition() {
    const size_t start = pos_;
    std::vector<QueryCondition> alternatives{conjunct()};
    while (continues("or")) {
      if (!startsCondition()) fail(conditionStarts());
      alternatives.push_back(conjunct());
    }
    return group(Kind::kOr, std::move(alternatives), start);
  }

  // conjunct = negation { [ "and" | "," ] negation }
  QueryCondition conjunct() {
    const size_t start = pos_;
    std::vector<QueryCondition> all{negation()};
    while (true) {
      if (at(",")) {
        ++pos_;
        if (!startsCondition()) {
          --pos_;  // the comma is the noun phrase's ("a cylinder, slightly bent, with ...") or the caller's
          break;
        }
      } else if (continues("and")) {
        if (!startsCondition()) fail(conditionStarts());
      } else if (!startsCondition()) {
        break;
      }
      all.push_back(negation());
    }
    return group(Kind::kAnd, std::move(all), start);
  }

  // One condition stays itself; several become an and / or labelled with the words they cover.
  QueryCondition group(Kind kind, std::vector<QueryCondition> children, size_t start) const {
    if (children.size() == 1) return std::move(children[0]);
    QueryCondition c;
    c.kind = kind;
    c.text = span(start, pos_);
    c.children = std::move(children);
    return c;
  }

  // "a" | "an", [ intensity ], adjective, section or edge word: "a square cross-section", "a very
  // round traverse section", "a rounded edge" (the article opens only these).
  bool startsArticleSection() const {
    if (!at("a") && !at("an")) return false;
    std::string m;
    size_t k = 1;
    k += matchPhrase(intensityWords_, &m, k);
    const size_t n = matchPhrase(adjectiveWords_, &m, k);
    return n > 0 && (matchPhrase(v_.sectionWords(), &m, k + n) > 0 || matchPhrase(v_.edgeWords(), &m, k + n) > 0);
  }

  // "of" [ "a" | "an" ] [ intensity ] adjective section, at pos_: a section said after "of".
  bool startsSectionAfterOf() const {
    std::string m;
    size_t k = 1;
    if (isWordAt(pos_ + k, {"a", "an"})) ++k;
    k += matchPhrase(intensityWords_, &m, k);
    const size_t n = matchPhrase(adjectiveWords_, &m, k);
    return n > 0 && matchPhrase(v_.sectionWords(), &m, k + n) > 0;
  }

  // negation = "not" negation | "(" condition ")" | [ intensity ] adjective [ section ]
  //          | ( "a" | "an" ) [ intensity ] adjective section
  QueryCondition negation() {
    // Deep nesting ("((((..." or "not not not ...") would exhaust the stack: a limit instead.
    struct Nesting {
      int& depth;
      explicit Nesting(int& d) : depth(++d) {}
      ~Nesting() { --depth; }
    } nesting(depth_);
    if (depth_ > kMaxNesting)
      throw Error(errc::kLimitExceeded,
                  "the query nests conditions deeper than " + std::to_string(kMaxNesting) + " levels (at character " +
                      std::to_string(tokens_[pos_].offset) + ")",
                  "text");
    const size_t start = pos_;
    if (acceptWord("not")) {
      if (!startsCondition()) fail(conditionStarts());
      QueryCondition c;
      c.kind = Kind::kNot;
      c.children.push_back(negation());
      c.text = span(start, pos_);
      return c;
    }
    if (acceptWord("(")) {
      if (!startsCondition()) fail(conditionStarts());
      QueryCondition inner = condition();
      if (!acceptWord(")")) fail({"')'", "'and'", "'or'"});
      return inner;
    }
    if (startsMeasure()) return measure();
    if (std::optional<QueryCondition> taper = taperPhrase()) return std::move(*taper);
    if (std::optional<QueryCondition> feature = featurePhrase()) return std::move(*feature);
    if (pos_ < tokens_.size() && descriptorIndex(tokens_[pos_].text) >= 0) {
      const std::string descriptor = tokens_[pos_++].text;
      FuzzyNumber set = degree();
      return descriptorCondition(descriptor, std::move(set), span(start, pos_));
    }
    // The part's edges ("round edges", "a softened corner", "sharp edges"): the degree of its
    // edge exponents, turned into a condition for the noun once it is read (turnEdges).
    if (std::optional<FuzzyNumber> degree = edgePhrase()) {
      QueryCondition c = descriptorCondition(v_.edgeDescriptor(), *degree, span(start, pos_));
      c.edges = QueryCondition::Edges::kNamed;
      c.edgeDegree = std::move(degree);
      return c;
    }
    std::string word;
    const bool article = startsArticleSection();
    if (article) ++pos_;
    const FuzzyNumber* intensity = nullptr;
    if (size_t n = matchPhrase(intensityWords_, &word)) {
      intensity = v_.intensity(word);
      pos_ += n;
    }
    const size_t n = matchPhrase(adjectiveWords_, &word);
    if (n == 0) fail({"an adjective (" + joinList(adjectiveWords_) + ")"});
    pos_ += n;
    const Adjective& adjective = *v_.adjective(word);
    std::string descriptor = adjective.descriptor;
    // section = a section word of the vocabulary: the adjective describes the traverse section alone.
    std::string sectionWord;
    if (const size_t k = matchPhrase(v_.sectionWords(), &sectionWord)) {
      const std::string* section = v_.sectionDescriptor(descriptor);
      if (!section)
        throw Error(errc::kInvalidParameter,
                    "'" + span(start, pos_ + k) + "' at character " + std::to_string(tokens_[start].offset) +
                        ": a section is described by its shape (" + joinList(sectionAdjectives()) + "); '" + word +
                        "' says nothing of it",
                    "text");
      descriptor = *section;
      pos_ += k;
    }
    if (!intensity && sectionWord.empty()) intensity = intensityAfterAdjective();
    // Where a taper goes says no more than the taper: "tapering to a point", "narrowing towards
    // the top".
    if (descriptor == "taperness" && sectionWord.empty()) pos_ += endTailLength(0);
    QueryCondition c = adjectiveCondition(adjective, descriptor, intensity, span(start, pos_));
    c.outline = adjective.outline && sectionWord.empty();
    // An edges.before_nouns adjective may say the edges of a square noun ("a rounded box").
    // With an intensity too: "a slightly rounded box" is a box with slightly rounded edges, as
    // "with slightly rounded edges" says (edgePhrase), not a slightly round shape that no box is.
    if (sectionWord.empty() && v_.saysEdgesBeforeNouns(word)) c.edgeDegree = intensity ? c.set : v_.edgeSet();
    return c;
  }

  // adjectives = { [ intensity ] adjective [ intensity_after ] [ "," | "and" ] } of a part
  // description, into d->adjectives; returns how many it read.
  size_t adjectiveUses(PartDescription* d) {
    size_t count = 0;
    std::string word;
    while (true) {
      const size_t start = pos_;
      const FuzzyNumber* intensity = nullptr;
      if (size_t n = matchPhrase(intensityWords_, &word)) {
        intensity = v_.intensity(word);
        pos_ += n;
      }
      const size_t n = matchPhrase(adjectiveWords_, &word);
      if (n == 0) {
        if (intensity) fail({"an adjective (" + joinList(adjectiveWords_) + ")"});
        return count;
      }
      pos_ += n;
      if (!intensity) intensity = intensityAfterAdjective();
      d->adjectives.push_back({v_.adjective(word), intensity, span(start, pos_)});
      ++count;
      const size_t beforeJoin = pos_;
      if (acceptWord(",") || acceptWord("and")) {
        std::string next;
        if (!matchPhrase(intensityWords_, &next) && !matchPhrase(adjectiveWords_, &next)) {
          // A comma before "with" ends the list ("a cylinder, slightly bent, with sharp edges").
          if (tokens_[beforeJoin].text == "," && at("with")) continue;
          fail({"an intensity (" + joinList(intensityWords_) + ")", "an adjective (" + joinList(adjectiveWords_) + ")"});
        }
      }
    }
  }

  // A width compared along the part is its taper: "gets thinner towards the top", "narrower at
  // one end", "much wider at the base", "slightly smaller to the tip".
  //   taper_phrase = [ taper_verb ] [ intensity_after ] comparative end_tail
  //   end_tail     = ( "to" | "towards" | "toward" | "at" ) [ "the" | "its" | "one" | "each" | "a" | "an" ] end_word
  // The comparatives are those of the vocabulary's adjectives of width, thickness and size
  // (thinner, narrower, wider, bigger, ...); the condition is taperness with the set of the
  // vocabulary's "tapered" (plain), or of the intensity before the comparative ("much": very).
  // Returns the phrase's length in tokens from the current one (0: none) and its intensity.
  size_t taperPhraseLength(const FuzzyNumber** intensity) const {
    if (!v_.adjective("tapered")) return 0;
    static const std::vector<std::string> verbs = {"get",    "gets",  "getting", "become", "becomes",
                                                   "becoming", "grow", "grows",   "growing"};
    size_t k = 0;
    const auto word = [&](size_t i) { return pos_ + i < tokens_.size() ? tokens_[pos_ + i].text : std::string(); };
    if (std::find(verbs.begin(), verbs.end(), word(k)) != verbs.end()) ++k;
    std::string said;
    const FuzzyNumber* graded = nullptr;
    if (const size_t n = matchPhrase(v_.intensityAfterWords(), &said, k)) {
      graded = v_.intensityAfter(said);
      k += n;
    }
    if (!isWidthComparative(word(k))) return 0;
    const size_t tail = endTailLength(k + 1);
    if (tail == 0) return 0;
    if (intensity) *intensity = graded;
    return k + 1 + tail;
  }

  // feature = [ "a" | "an" ] [ feature-degree ] feature-noun (featureNouns)
  //         | [ "the" | "its" ] end-word cut-word [ "off" | "away" ]   ("its top cut off": truncated)
  // : the tokens it spans at pos_ (0: none), with its adjective and intensity (null: plain).
  size_t featurePhraseLength(const Adjective** adjective, const FuzzyNumber** intensity) const {
    const auto word = [&](size_t i) { return pos_ + i < tokens_.size() ? tokens_[pos_ + i].text : std::string(); };
    // A tip cut off is a taper short of a point: "a cone with its top cut off", "pyramid with top
    // cutted" (as a writer in another language says it).
    static const std::vector<std::string> kTips = {"top", "tip", "point", "apex", "peak"};
    static const std::vector<std::string> kCuts = {"cut", "cutted", "chopped", "sliced", "sawn", "removed"};
    if (const Adjective* truncated = v_.adjective("truncated")) {
      const size_t t = word(0) == "the" || word(0) == "its" ? 1 : 0;
      if (contains(kTips, word(t)) && contains(kCuts, word(t + 1))) {
        if (adjective) *adjective = truncated;
        if (intensity) *intensity = nullptr;
        return t + 2 + (word(t + 2) == "off" || word(t + 2) == "away" ? 1 : 0);
      }
    }
    size_t k = word(0) == "a" || word(0) == "an" ? 1 : 0;
    const FuzzyNumber* graded = nullptr;
    for (const auto& [w, term] : query_tokens::degreeWords())
      if (word(k) == w && v_.intensity(term)) {
        graded = v_.intensity(term);
        ++k;
        break;
      }
    for (const auto& [noun, participle] : featureNouns())
      if (word(k) == noun && v_.adjective(participle)) {
        if (adjective) *adjective = v_.adjective(participle);
        if (intensity) *intensity = graded;
        return k + 1;
      }
    return 0;
  }

  std::optional<QueryCondition> featurePhrase() {
    const Adjective* adjective = nullptr;
    const FuzzyNumber* intensity = nullptr;
    const size_t n = featurePhraseLength(&adjective, &intensity);
    if (n == 0) return std::nullopt;
    const size_t start = pos_;
    pos_ += n;
    return adjectiveCondition(*adjective, adjective->descriptor, intensity, span(start, pos_));
  }

  // An adjective's condition on `descriptor` (its own, or its section's): the intensity's set,
  // mirrored for a low pole, or without one the plain set, which rises as a ramp unless the
  // adjective names a middle of its own.
  QueryCondition adjectiveCondition(const Adjective& adjective, const std::string& descriptor,
                                    const FuzzyNumber* intensity, std::string text) const {
    FuzzyNumber set = intensity ? (adjective.lowPole ? mirroredDegrees(*intensity) : *intensity) : v_.plainSet(adjective);
    QueryCondition c = descriptorCondition(descriptor, std::move(set), std::move(text));
    c.plainRamp = !intensity && !adjective.set;
    return c;
  }

  std::optional<QueryCondition> taperPhrase() {
    const FuzzyNumber* intensity = nullptr;
    const size_t n = taperPhraseLength(&intensity);
    if (n == 0) return std::nullopt;
    const size_t start = pos_;
    pos_ += n;
    QueryCondition c = descriptorCondition("taperness", intensity ? *intensity : v_.plainSet(*v_.adjective("tapered")),
                                           span(start, pos_));
    c.plainRamp = !intensity && !v_.adjective("tapered")->set;
    return c;
  }

  // end_tail from k tokens ahead of the current one: its length, or 0.
  size_t endTailLength(size_t k) const {
    static const std::vector<std::string> to = {"to", "towards", "toward", "at"};
    static const std::vector<std::string> which = {"the", "its", "one", "each", "a", "an"};
    static const std::vector<std::string> ends = {"top", "bottom", "end", "ends", "tip", "base", "point"};
    const auto word = [&](size_t i) { return pos_ + i < tokens_.size() ? tokens_[pos_ + i].text : std::string(); };
    if (std::find(to.begin(), to.end(), word(k)) == to.end()) return 0;
    size_t n = 1;
    if (std::find(which.begin(), which.end(), word(k + n)) != which.end()) ++n;
    if (std::find(ends.begin(), ends.end(), word(k + n)) == ends.end()) return 0;
    // Not a direction phrase: "tapered to the top of a box", "spiky to the top right of a sphere".
    std::string direction;
    const size_t d = matchPhrase(directionWords_, &direction, k + n);
    if (d > 1 || word(k + n + std::max<size_t>(d, 1)) == "of") return 0;
    return n + 1;
  }

  // Whether `w` is the comparative of an adjective of width, thickness or size ("thinner",
  // "wider", "bigger", "tinier": Vocabulary::widthComparatives, listed when it is loaded).
  bool isWidthComparative(const std::string& w) const {
    const std::vector<std::string>& c = v_.widthComparatives();
    return std::binary_search(c.begin(), c.end(), w);
  }

  // An intensity after its adjective, as people put it ("bent slightly", "twisted a little", "bent
  // a lot": Vocabulary::intensityAfter), or null. Not one that opens the next adjective: "bent
  // slightly tapered" is plain bent and slightly tapered, as the words before an adjective go.
  const FuzzyNumber* intensityAfterAdjective() {
    std::string words, next;
    const size_t n = matchPhrase(v_.intensityAfterWords(), &words);
    if (n == 0 || matchPhrase(adjectiveWords_, &next, n) > 0 || matchPhrase(intensityWords_, &next, n) > 0)
      return nullptr;
    pos_ += n;
    return v_.intensityAfter(words);
  }

  // edge = [ "a" | "an" ] [ intensity ] adjective edge-word, the adjective one of the edge
  // descriptor's ("rounded edges", "a softened corner") or a sharp one ("sharp edges", "square
  // corners": Vocabulary::sharpEdgeWords): the degree of the part's edge exponents (edges.h).
  // Plain, the vocabulary's edge or sharp edge set; with an intensity its set, mirrored for sharp
  // edges (the low end of the descriptor) as for a low-pole adjective. Where the tokens at pos_
  // are no edge phrase, nothing is read and the answer is empty.
  std::optional<FuzzyNumber> edgePhrase() {
    size_t k = at("a") || at("an") ? 1 : 0;
    std::string word;
    const FuzzyNumber* intensity = nullptr;
    if (const size_t n = matchPhrase(intensityWords_, &word, k)) {
      intensity = v_.intensity(word);
      k += n;
    }
    const size_t n = matchPhrase(adjectiveWords_, &word, k);
    if (n == 0) return std::nullopt;
    const Adjective& adjective = *v_.adjective(word);
    const bool sharp = contains(v_.sharpEdgeWords(), word);
    if (!sharp && adjective.descriptor != v_.edgeDescriptor()) return std::nullopt;
    std::string edgeWord;
    const size_t e = matchPhrase(v_.edgeWords(), &edgeWord, k + n);
    if (e == 0) return std::nullopt;
    pos_ += k + n + e;
    if (sharp) return intensity ? mirroredDegrees(*intensity) : v_.sharpEdgeSet();
    if (!intensity) return v_.edgeSet();
    return adjective.lowPole ? mirroredDegrees(*intensity) : *intensity;
  }

  // Every pending edge leaf of `c` (QueryCondition::edgeDegree) resolved for `noun`: named edges
  // ("with sharp edges") become the set of the edge descriptor a part of the noun with those
  // edges has (edgeDescriptorSet: a cylinder's round section stays round). A plain adjective
  // before a noun with a squariness condition says its edges too ("a rounded box"); before any
  // other noun it stays the adjective ("a rounded ball" is a round ball), and so it does under
  // "not" ("a box that is not rounded" is a square box).
  void turnEdges(QueryCondition* c, const Noun& noun, bool negated = false) const {
    if (c->kind == Kind::kDescriptor && c->edgeDegree) {
      if (c->edges == QueryCondition::Edges::kNone && isSquareNoun(noun) && !negated)
        c->edges = QueryCondition::Edges::kBeforeNoun;
      if (c->edges != QueryCondition::Edges::kNone) c->set = edgeDescriptorSet(*c->edgeDegree, &noun, v_);
      c->edgeDegree.reset();
    }
    for (QueryCondition& child : c->children) turnEdges(&child, noun, negated || c->kind == Kind::kNot);
  }

  // A measured length of a noun turned about its own z axis (a round section, and z its longest
  // axis: a cylinder, a rod, a cone) is its axial length, the height descriptor, whatever its
  // diameter: "a cylinder with diameter 2 and length 1" is a stubby cylinder, whose longest
  // extent is its diameter. (A part made from those words sets that axis: part_from_words.h.)
  // Elsewhere "long" measures the longest extent ("a board 8 long").
  void turnAxialLength(QueryCondition* c, const Noun& noun) const {
    if (c->kind == Kind::kDescriptor && c->measure && c->descriptor == "length" && axial(noun)) {
      c->descriptor = "height";
      c->axialLength = true;
    }
    if (c->kind == Kind::kAnd)
      for (QueryCondition& child : c->children) turnAxialLength(&child, noun);
  }
  // A number of the noun's params, or `otherwise` where it gives none.
  static double nounParam(const Noun& noun, const char* name, double otherwise) {
    if (!noun.params.is_object()) return otherwise;
    const auto it = noun.params.find(name);
    return it != noun.params.end() && it->is_number() ? it->get<double>() : otherwise;
  }
  static bool axial(const Noun& noun) {
    return nounParam(noun, "eps2", 0.0) == 1.0 && nounParam(noun, "a2", 1.0) == 1.0 && nounParam(noun, "a3", 1.0) >= 1.0;
  }

  // The profile a flat noun keeps when the words set its outline (a section descriptor): for each
  // of its exponent-shape conditions that the words replace, the degrees its prototype (its params)
  // has with the section the words say, as trap(lo − 0.15, lo − 0.05, hi + 0.05, hi + 0.15), the
  // tolerance of the vocabulary's disc and cylinder around theirs. [lo, hi] is the image, through
  // the section rule (roundness d is eps2 = d, squariness d is eps2 = 1 − d), of the degrees a
  // part made from the words has: the core of a plain adjective's set (its part takes one degree
  // there), else the support (an intensity's set, which its part takes whole). So "a round plate"
  // asks for a disc's squariness 0.45 (flat faces, sharp rims, a round outline), which a ball
  // squashed flat (0) does not have, and the part made from the words has.
  std::vector<QueryCondition> profileConditions(const Noun& noun, const std::vector<const QueryCondition*>& said,
                                                const std::function<bool(const QueryCondition&)>& graded,
                                                const std::string& nounText) const {
    std::vector<QueryCondition> out;
    if (!noun.flat || !noun.params.is_object()) return out;
    const QueryCondition* outline = nullptr;
    for (const QueryCondition* c : said)
      if (c->kind == Kind::kDescriptor && v_.wholeShapeDescriptor(c->descriptor)) outline = c;
    if (!outline) return out;
    const Interval made = outline->plainRamp ? outline->set.core() : outline->set.support();
    const bool round = *v_.wholeShapeDescriptor(outline->descriptor) == "roundness";
    PlacedSuperquadric prototype;
    prototype.params.eps1 = nounParam(noun, "eps1", 1.0);
    for (const NounCondition& c : noun.conditions) {
      if (!isExponentShape(c.descriptor) || v_.wholeShapeDescriptor(c.descriptor) ||
          !overriddenByWords(c, noun, said, graded))
        continue;
      double lo = 1.0, hi = 0.0;
      for (const double d : {made.lo, made.hi}) {  // the degrees are monotone in eps2 over [0.01, 1]
        const double e = std::clamp(round ? d : 1.0 - d, kLeastDegree, 1.0);
        prototype.params.eps2 = e;
        const double v = descriptorDegree(descriptorIndex(c.descriptor), prototype);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      out.push_back(descriptorCondition(
          c.descriptor,
          FuzzyNumber::trapezoidal(std::max(0.0, lo - 0.15), std::max(0.0, lo - 0.05), std::min(1.0, hi + 0.05),
                                   std::min(1.0, hi + 0.15)),
          nounText + ": " + c.descriptor));
    }
    return out;
  }

  // Every outline leaf of `c` resolved for `noun` (Vocabulary::descriptorOn): on the section's
  // descriptor where the noun is flat, on its own elsewhere; either way no longer pending.
  void turnOutlines(QueryCondition* c, const Noun& noun) const {
    if (c->kind == Kind::kDescriptor && c->outline) {
      if (noun.flat)
        if (const std::string* section = v_.sectionDescriptor(c->descriptor)) c->descriptor = *section;
      c->outline = false;
    }
    for (QueryCondition& child : c->children) turnOutlines(&child, noun);
  }

  // The adjectives whose descriptor has a section descriptor ("round", "square", ...).
  std::vector<std::string> sectionAdjectives() const {
    std::vector<std::string> out;
    for (const std::string& a : adjectiveWords_)
      if (v_.sectionDescriptor(v_.adjective(a)->descriptor)) out.push_back(a);
    return out;
  }

  // The start of a distance or a direction phrase after a noun phrase.
  bool startsRelation() const {
    if (pos_ >= tokens_.size()) return false;
    if (tokens_[pos_].number || contains(kApproximately, tokens_[pos_].text) || at("between") || at("to")) return true;
    std::string m;
    return matchPhrase(distanceWords_, &m) > 0 || matchPhrase(directionWords_, &m) > 0;
  }

  // distance = number_phrase [ "unit" | "units" ] | distance_word   ("about 2 units above a cube")
  std::optional<FuzzyNumber> optionalDistance() {
    std::string word;
    if (size_t n = matchPhrase(distanceWords_, &word)) {
      pos_ += n;
      return *v_.distance(word);
    }
    std::optional<FuzzyNumber> d = numberPhrase("distance");
    if (d && !acceptWord("units")) acceptWord("unit");
    return d;
  }

  // number_phrase (query/json/number_phrases.h): N | ("exactly"|"about"|...) N | "between" N "and" N
  std::optional<FuzzyNumber> numberPhrase(const char* what) {
    const size_t start = pos_;
    if (at("between")) {
      ++pos_;
      expectNumber();
      expectWord("and");
      expectNumber();
    } else if (pos_ < tokens_.size() && contains(kApproximately, tokens_[pos_].text)) {
      ++pos_;
      expectNumber();
    } else if (pos_ < tokens_.size() && tokens_[pos_].number) {
      ++pos_;
    } else {
      return std::nullopt;
    }
    std::string phrase;
    for (size_t i = start; i < pos_; ++i) phrase += (i > start ? " " : "") + tokens_[i].text;
    try {
      return parseNumberPhrase(phrase);
    } catch (const Error& e) {
      throw Error(errc::kInvalidParameter,
                  std::string("bad ") + what + " '" + phrase + "' at character " + std::to_string(tokens_[start].offset) +
                      ": " + e.what(),
                  "text");
    }
  }

  // degree = [ "is" ] ( number_phrase | "at" "least" NUMBER | "at" "most" NUMBER ), in [0, 1]:
  // "bendness at least 0.5" is trap(0.5, 0.5, 1, 1), "roundness about 1" the triangle of about 1
  // restricted to [0, 1].
  FuzzyNumber degree() {
    acceptWord("is");
    const size_t start = pos_;
    if (acceptWord("at")) {
      const bool least = acceptWord("least");
      if (!least && !acceptWord("most")) fail({"'least'", "'most'"});
      if (pos_ >= tokens_.size() || !tokens_[pos_].number) fail({"a number in [0, 1]"});
      const double x = std::strtod(tokens_[pos_].text.c_str(), nullptr);
      checkDegree(x, start);
      ++pos_;
      return least ? FuzzyNumber::trapezoidal(x, x, 1, 1) : FuzzyNumber::trapezoidal(0, 0, x, x);
    }
    std::optional<FuzzyNumber> set = numberPhrase("degree");
    if (!set) fail({"a degree ('about 0.3', '0.5', 'between 0.2 and 0.4', 'at least 0.7', 'at most 0.2')"});
    checkDegree(set->core().lo, start);
    checkDegree(set->core().hi, start);
    return restrictedToDegrees(*set);
  }

  void checkDegree(double x, size_t start) const {
    if (x < 0.0 || x > 1.0)
      throw Error(errc::kInvalidParameter,
                  "a descriptor degree is in [0, 1]; the one at character " + std::to_string(tokens_[start].offset) +
                      " is not",
                  "text");
  }

  void expectNumber() {
    if (pos_ >= tokens_.size() || !tokens_[pos_].number) fail({"a number"});
    ++pos_;
  }

  // direction_phrase = [ "to" "the" ] direction "of" | a phrase of the vocabulary ("above")
  Direction directionPhrase() {
    const bool to = acceptWord("to");
    if (to) acceptWord("the");
    std::string word;
    const size_t n = matchPhrase(directionWords_, &word);
    if (n == 0) fail({"a direction (" + joinList(directionWords_) + ")"});
    pos_ += n;
    const Direction& d = *v_.direction(word);
    if (d.word != word && !to) return d;  // a phrase: "above", "in front of"
    if (!acceptWord("of")) fail({"'of'"});
    return d;
  }

  const std::string& text_;
  const Vocabulary& v_;
  std::vector<Token> owned_;  // the tokens when the parser tokenised the text itself
  TokenView tokens_;
  size_t pos_ = 0;
  // The two sides of the last base measure() read ("base 2 x 2", "a 1 x 1 base"): measuresAfterNoun
  // sorts them with a height said beside them.
  std::optional<std::pair<FuzzyNumber, FuzzyNumber>> lastBase_;
  const Noun* partNoun_ = nullptr;  // a part description's noun, once read (measuresAfterNoun)
  const bool prefix_;  // nounPhraseAt: the phrase is followed by the caller's words
  enum class Entry { kQuery, kPartDescription };
  Entry entry_ = Entry::kQuery;  // which production a whole text's parse started from (didYouMean retries it)
  bool suggest_ = true;          // false inside a didYouMean trial and when only asked whether a text reads
  int depth_ = 0;  // nesting of conditions (parentheses, not), bounded by kMaxNesting
  // The vocabulary's word lists.
  const std::vector<std::string>&intensityWords_, &adjectiveWords_, &nounWords_, &directionWords_, &distanceWords_;
};

}  // namespace

namespace {
void readOverDegreeDomains(QueryCondition* c) {
  if (c->kind == QueryCondition::Kind::kDescriptor) {
    const Interval domain = degreeDomain(descriptorIndex(c->descriptor));
    c->set = withinDegrees(c->set, domain.lo, domain.hi);
    if (c->asked) *c->asked = withinDegrees(*c->asked, domain.lo, domain.hi);
  }
  for (QueryCondition& child : c->children) readOverDegreeDomains(&child);
}
}  // namespace

LinguisticQuery withinDegreeDomains(const LinguisticQuery& query) {
  LinguisticQuery read = query;
  readOverDegreeDomains(&read.root);
  return read;
}

LinguisticQuery parseLinguisticQuery(const std::string& text, const Vocabulary& vocabulary) {
  return Parser(text, vocabulary).parse();
}

bool knowsLinguisticWord(const std::string& word, const Vocabulary& vocabulary) {
  const auto said = [&](const std::vector<std::pair<std::string, std::string>>& table) {
    return std::any_of(table.begin(), table.end(), [&](const auto& p) { return p.first == word; });
  };
  // The feature nouns are not among them: a text that reads whole reads them in their phrase,
  // and elsewhere they are verbs ("rods which taper" is a stative verb's route, "which are
  // tapered"). Their grading words are: left unknown, "slight" routed to thin.
  return vocabulary.knowsWord(word) || contains(grammarWords(), word) || descriptorIndex(word) >= 0 ||
         std::binary_search(measureWords().begin(), measureWords().end(), word) || said(query_tokens::degreeWords());
}

const std::vector<std::string>& measureWords() {
  static const std::vector<std::string> words = [] {
    std::vector<std::string> out = {"x", "by", "unit", "units"};
    for (const auto* table : {&dimensionsAfterNumber(), &dimensionsBeforeNumber()})
      for (const DimensionWord& d : *table)
        for (size_t at = 0; at < d.words.size();) {
          size_t end = d.words.find(' ', at);
          if (end == std::string::npos) end = d.words.size();
          out.push_back(d.words.substr(at, end - at));
          at = end + 1;
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }();
  return words;
}

std::vector<std::string> correctableWords(const Vocabulary& vocabulary) {
  std::vector<std::string> words(descriptorNames().begin(), descriptorNames().end());
  for (const std::string& w : measureWords())
    if (w.size() >= 3 && !contains(grammarWords(), w)) words.push_back(w);
  for (const auto* list : {&vocabulary.intensityWords(), &vocabulary.adjectiveWords(), &vocabulary.nounWords(),
                           &vocabulary.directionWords(), &vocabulary.distanceWords(), &vocabulary.sectionWords(),
                           &vocabulary.edgeWords()})
    for (const std::string& phrase : *list)
      for (size_t at = 0; at < phrase.size();) {
        size_t end = phrase.find(' ', at);
        if (end == std::string::npos) end = phrase.size();
        // The content words of the phrases ("in front of" gives "front"), not the little ones.
        const std::string word = phrase.substr(at, end - at);
        if (word.size() >= 3 && !contains(grammarWords(), word)) words.push_back(word);
        at = end + 1;
      }
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}

bool isLinguisticQuery(const std::string& text, const Vocabulary& vocabulary) {
  try {
    Parser parser(text, vocabulary);
    parser.noSuggestions();
    parser.parse();
    return true;
  } catch (const Error&) {
    return false;
  }
}

const std::vector<std::string>& queryVerbs() {
  static const std::vector<std::string> verbs = {"find", "show", "search", "get", "list"};
  return verbs;
}

const std::vector<std::string>& queryArticles() {
  static const std::vector<std::string> articles = {"a", "an", "the", "any", "some", "all"};
  return articles;
}

NounPhraseAt parseNounPhraseAt(const std::string& text, size_t from, size_t to, const Vocabulary& vocabulary) {
  return Parser(text, vocabulary, from, to, true).nounPhraseAt();
}

struct NounPhraseReader::Tokens {
  std::vector<Token> tokens;  // of text[from, end) for the `from` of the first call
};

NounPhraseReader::NounPhraseReader(const std::string& text, const Vocabulary& vocabulary)
    : text_(text), vocabulary_(vocabulary) {}
NounPhraseReader::~NounPhraseReader() = default;

NounPhraseAt NounPhraseReader::at(size_t from) {
  // Tokens never span blanks, parentheses or commas, so tokenising from an earlier position gives
  // the same tokens from `from` on when `from` starts one; elsewhere the phrase is read on its own.
  if (!tokens_ || (!tokens_->tokens.empty() && from < tokens_->tokens.front().offset)) {
    tokens_ = std::make_unique<Tokens>();
    tokens_->tokens = readableWords(tokenize(text_, from, text_.size()), vocabulary_);
  }
  const std::vector<Token>& all = tokens_->tokens;
  const auto first = std::lower_bound(all.begin(), all.end(), from,
                                      [](const Token& t, size_t offset) { return t.offset < offset; });
  if (first != all.begin() && std::prev(first)->end > from) return parseNounPhraseAt(text_, from, std::string::npos, vocabulary_);
  const TokenView view{all.data() + (first - all.begin()), size_t(all.end() - first)};
  return Parser(text_, vocabulary_, view, true).nounPhraseAt();
}

PartDescription parsePartDescription(const std::string& text, const Vocabulary& vocabulary) {
  return Parser(text, vocabulary).partDescription();
}

}  // namespace fsdb
