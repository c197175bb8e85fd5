// See query/structural/csg_query_text.h.
#include "query/structural/csg_query_text.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "query/document/csg_text.h"
#include "query/json/fuzzy_json.h"
#include "query/json/number_phrases.h"
#include "query/linguistic/query_tokens.h"

namespace fsdb {
namespace {

// Description leaves enter shapeGraph as inline parts with this name prefix and their index; no
// stored name can hold the control character (documents.h refuses control characters in names).
const std::string kPlaceholder = "\x1f" "csg-query-leaf-";

nlohmann::json placeholder(size_t index) {
  return {{"part", {{"name", kPlaceholder + std::to_string(index)}, {"params", {{"a1", 1}}}}}};
}

bool isWordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '\'' || c == '.';
}

const std::vector<std::string> kOperationWords = {"union", "intersection", "difference", "minus",
                                                  "without", "plus", "intersected"};

// Two-word joiners of a list (a union), besides "and", "," and "plus".
const std::pair<const char*, const char*> kUnionPhrases[] = {
    {"united", "with"}, {"combined", "with"}, {"joined", "with"}, {"joined", "to"}, {"together", "with"},
    {"along", "with"}};

// After "with Y": Y is cut away from what comes before (one-word phrases have "" second).
const std::pair<const char*, const char*> kCutOutPhrases[] = {
    {"cut", "out"},   {"cut", "away"},      {"taken", "out"}, {"carved", "out"},
    {"hollowed", "out"}, {"removed", ""}, {"subtracted", ""}};

// Words that make the part after them hollow (PhraseParser::hollow): "a hollow cylinder" (a tube),
// "an annular disc" (ring-shaped: a disc with a hole through it, a washer).
const std::vector<std::string> kHollowWords = {"hollow", "annular"};
// Participles that say a part has a hole: "a drilled block" is "a block with a hole".
const std::vector<std::string> kDrilledWords = {"drilled", "bored", "pierced", "perforated", "holed"};

bool contains(const std::vector<std::string>& list, const std::string& w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

struct Word {
  std::string text;  // lower case
  size_t offset;
};

// The words of the phrase form: runs of characters other than blanks and "(),", and those three.
// A word that is a number as a whole: "3", "-0.5", "2.5e+32" (not "inf", "+3" or "3x").
bool isNumberWord(const std::string& w) {
  char* end = nullptr;
  std::strtod(w.c_str(), &end);
  return !w.empty() && end == w.c_str() + w.size() &&
         (std::isdigit(static_cast<unsigned char>(w[0])) || w[0] == '-' || w[0] == '.');
}

std::vector<Word> words(const std::string& text) {
  std::vector<Word> out;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '(' || c == ')' || c == ',') {
      out.push_back({std::string(1, c), i++});
    } else {
      Word w{"", i};
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && text[i] != '(' &&
             text[i] != ')' && text[i] != ',')
        w.text += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i++])));
      out.push_back(w);
    }
  }
  return out;
}

// The text with a hollow or drilled word that follows a run of adjectives and intensities moved
// before them ("a bent hollow tube" is "a hollow bent tube", "a big drilled block" "a drilled big
// block"), and a hollow word that follows its noun before the noun ("tube hollow"), where the
// grammar reads it: the hollowed or drilled part is the noun phrase after it,
// and the noun phrases are read from the text's characters, so the words move there.
std::string hollowWordsFirst(const std::string& text, const Vocabulary& vocabulary) {
  std::string out = text;
  const std::vector<Word> ws = words(text);
  for (size_t k = 1; k < ws.size(); ++k) {
    if (!contains(kHollowWords, ws[k].text) && !contains(kDrilledWords, ws[k].text)) continue;
    size_t j = k;
    // A hollow word right after its noun, ending the noun phrase, goes before it and its
    // adjectives too ("tube hollow which is bent"). ("a plate drilled with a rod" is the grammar's
    // own difference: drilled words stay.)
    const bool nextStartsPhrase = k + 1 < ws.size() && (vocabulary.noun(ws[k + 1].text) || vocabulary.adjective(ws[k + 1].text) ||
                                                        vocabulary.intensity(ws[k + 1].text) || contains(queryArticles(), ws[k + 1].text));
    if (contains(kHollowWords, ws[k].text) && vocabulary.noun(ws[k - 1].text) && !nextStartsPhrase) --j;
    while (j > 0 && (vocabulary.adjective(ws[j - 1].text) || vocabulary.intensity(ws[j - 1].text))) --j;
    if (j == k) continue;
    // out keeps text's length and offsets outside the run: the run and the word swap places.
    const std::string run = text.substr(ws[j].offset, ws[k - 1].offset + ws[k - 1].text.size() - ws[j].offset);
    const std::string word = text.substr(ws[k].offset, ws[k].text.size());
    const std::string between = text.substr(ws[k - 1].offset + ws[k - 1].text.size(),
                                            ws[k].offset - (ws[k - 1].offset + ws[k - 1].text.size()));
    out.replace(ws[j].offset, run.size() + between.size() + word.size(), word + between + run);
  }
  return out;
}

// The phrase form: recursive descent over `words`, one function per production of the header; the
// leaves are noun phrases read by the linguistic parser from their first character on.
class PhraseParser {
 public:
  PhraseParser(const std::string& text, const Vocabulary& vocabulary, std::vector<CsgQueryLeaf>& leaves)
      : owned_(hollowWordsFirst(text, vocabulary)),
        text_(owned_),
        words_(query_tokens::readableWords(words(text_), vocabulary)),  // as the linguistic parser reads them
        leaves_(leaves),
        phrases_(text_, vocabulary),
        v_(vocabulary) {}

  nlohmann::json parse() {
    if (words_.empty()) fail({"a query such as 'the union of a bent cylinder and a sphere'"});
    skipRequest();
    skipLeadIn();
    nlohmann::json tree = expr();
    if (pos_ < words_.size()) fail({"'minus'", "'and'", "','", "'plus'", "'intersected with'", "the end of the query"});
    return tree;
  }

 private:
  // A chain of minus nests (differences are not associative): each link counts as a nesting level.
  // subtraction = ( "minus" | "without" | "drilled" [ "through" ] [ "with" | "by" ] ) list
  //             | hole_lead hole | "with" meet cut_out   (cut_out: "cut out", "removed", ...)
  // hole_lead = "with" | ( "that" | "which" ) ( "has" | "have" )
  nlohmann::json expr() {
    nlohmann::json left = list();
    int links = 0;
    while (true) {
      nlohmann::json subtrahend;
      if (!pendingCut_.is_null()) {
        subtrahend = std::move(pendingCut_);  // list() met "with Y cut out"
        pendingCut_ = nullptr;
      } else if (acceptAny({"minus", "without"}) || acceptDrilled()) {
        subtrahend = list();
      } else if (const size_t lead = holeLead()) {
        pos_ += lead;  // "with", "which has"
        subtrahend = hole();
      } else {
        break;
      }
      if (depth_ + ++links > kMaxNesting) tooDeep();
      nlohmann::json operands = nlohmann::json::array();
      operands.push_back(std::move(left));
      operands.push_back(std::move(subtrahend));
      left = node("difference", std::move(operands));
    }
    return left;
  }

  // "with" [ article ] [ SHAPE-shaped | ADJECTIVE-FORM ] "hole": the hole is the shape cut out.
  bool atHole() const { return at("with") && holeLead() == 1; }

  // The words that lead a hole at pos_ (0: no hole follows): "with", or a relative clause that
  // says the part has it ("a cube which has a hole", "a block that has a hole in it"), as a
  // writer in another language or in a hurry puts it.
  size_t holeLead() const {
    size_t lead = 0;
    if (at("with")) {
      lead = 1;
    } else if ((at("that") || at("which")) && pos_ + 1 < words_.size() &&
               (words_[pos_ + 1].text == "has" || words_[pos_ + 1].text == "have")) {
      lead = 2;
    } else {
      return 0;
    }
    size_t i = pos_ + lead;
    if (i < words_.size() && contains(queryArticles(), words_[i].text)) ++i;
    i += holeSizeWords(i);
    if (i < words_.size() && words_[i].text == "hole") return v_.plainHoleNoun().empty() ? 0 : lead;
    return i + 1 < words_.size() && words_[i + 1].text == "hole" && !holeNoun(words_[i].text).empty() ? lead : 0;
  }

  // The words of a hole's size at word i, as an engineer puts it before the hole ("a 0.8 hole",
  // "a 0.5 unit hole"): a positive number and "unit(s)" if said; 0 for none.
  size_t holeSizeWords(size_t i) const {
    if (!isNumberAt(i) || std::strtod(words_[i].text.c_str(), nullptr) <= 0) return 0;
    return i + 1 < words_.size() && (words_[i + 1].text == "unit" || words_[i + 1].text == "units") ? 2 : 1;
  }

  // The noun a hole's shape word names: "cylinder-shaped" (any noun of the vocabulary with
  // "-shaped"), or a word of the vocabulary's holes ("cylindrical", "spherical", ...); "" for none.
  std::string holeNoun(const std::string& word) const {
    const std::string suffix = "-shaped";
    if (word.size() > suffix.size() && word.compare(word.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string noun = word.substr(0, word.size() - suffix.size());
      return v_.noun(noun) ? noun : "";
    }
    const std::string* noun = v_.holeNoun(word);
    return noun ? *noun : "";
  }

  // hole = [ article ] [ NUMBER [ "unit(s)" ] ] [ shape word ] "hole" [ "drilled" ] [ ( "through" | "in" | "into" ) [ "it" | where ] ],
  // where = [ "the" ] ( "middle" | "center" | "centre" ), at holeLead(): a description leaf of the
  // noun its shape word names (a cylinder when none: a drilled hole), with the words as written.
  // Where the hole is ("in the middle", "through the center") is not placed: a hole's leaf is
  // compared by its noun, and the catalogue's holes are central.
  nlohmann::json hole() {
    const size_t from = words_[pos_].offset;
    acceptAny(queryArticles());
    // A size said before the hole is its width: the leaf is "a cylinder 0.8 across".
    std::string across;
    if (const size_t k = holeSizeWords(pos_)) {
      across = words_[pos_].text;
      pos_ += k;
    }
    std::string noun = v_.plainHoleNoun();  // "a cube with a hole": drilled
    if (!at("hole")) noun = holeNoun(words_[pos_++].text);
    const size_t end = words_[pos_].offset + words_[pos_].text.size();
    ++pos_;  // "hole"
    // How the hole was made adds nothing: "a slab with a hole drilled through it", "bored through
    // it", "with a hole in it" (word_routes.h reads "cut", "punched" as "drilled").
    const bool drilled = acceptAny(kDrilledWords);
    if (acceptAny({"through", "in", "into"}) || drilled) {
      if (!accept("it")) {
        const size_t before = pos_;
        accept("the");
        if (!acceptAny({"middle", "center", "centre"})) pos_ = before;
      }
    }
    head_ = plainNounLeaf(noun, text_.substr(from, end - from), across);
    return placeholder(head_);
  }

  // A leaf of the plain noun ("a cylinder") with `text` as its words (a hole's, or "hollow"): the
  // part a hole or a hollow cuts away, `across` wide when given ("0.8"). Returns its index.
  size_t plainNounLeaf(const std::string& noun, std::string text, const std::string& across = "") {
    CsgQueryLeaf out;
    out.text = std::move(text);
    const std::string words = "a " + noun + (across.empty() ? "" : " " + across + " across");
    out.condition = parseNounPhraseAt(words, 0, std::string::npos, v_).query;
    leaves_.push_back(std::move(out));
    return leaves_.size() - 1;
  }

  // hollow = ( "hollow" | "annular" ) noun_phrase, after that `word`: the part minus a part of its
  // own noun ("a hollow cylinder" is a tube, "a hollow ball" a shell, "an annular disc" a washer),
  // as a hole is a part of the noun its shape word names. The hollow leaf is the plain noun; the
  // outer one keeps every word said.
  nlohmann::json hollow(const std::string& word) {
    nlohmann::json outer = leaf();
    const size_t outerLeaf = leaves_.size() - 1;
    const std::string noun = leaves_[outerLeaf].condition ? nounOf(leaves_[outerLeaf].condition->root) : "";
    const Noun* n = noun.empty() ? nullptr : v_.noun(noun);
    if (!n || n->params.is_null())
      throw Error(errc::kInvalidParameter,
                  "'" + word + " " + leaves_[outerLeaf].text + "' needs a noun with a shape, as in 'a " + word +
                      " cylinder'",
                  "text");
    nlohmann::json operands = nlohmann::json::array();
    operands.push_back(std::move(outer));
    operands.push_back(placeholder(plainNounLeaf(noun, word)));
    return node("difference", std::move(operands));
  }

  // drilled = ( "drilled" | "bored" | "pierced" | "perforated" | "holed" ) noun_phrase, after that
  // `word`: the part minus a hole's part, as "a block with a hole" reads ("a drilled block").
  nlohmann::json drilledPart(const std::string& word) {
    nlohmann::json operands = nlohmann::json::array();
    operands.push_back(leaf());
    operands.push_back(placeholder(plainNounLeaf(v_.plainHoleNoun(), word)));
    return node("difference", std::move(operands));
  }

  // The noun a parsed noun phrase names (QueryCondition::noun), or "" when it names none.
  static std::string nounOf(const QueryCondition& c) {
    if (!c.noun.empty()) return c.noun;
    for (const QueryCondition& child : c.children)
      if (std::string noun = nounOf(child); !noun.empty()) return noun;
    return "";
  }

  // Words that say the operand before them is cut away: "cut out", "cut away", "removed",
  // "taken out", "subtracted", "carved out", "hollowed out". Accepts them.
  bool acceptCutOut() {
    for (const auto& [first, second] : kCutOutPhrases) {
      if (second[0] == '\0' ? accept(first) : acceptPair(first, second)) return true;
    }
    return false;
  }

  // "drilled" ( [ "through" ] ( "with" | "by" ) | "through" ): the next list is cut away.
  bool acceptDrilled() {
    if (!at("drilled") || !nextIsAny({"with", "through", "by"})) return false;
    pos_ += 2;
    if (words_[pos_ - 1].text == "through") acceptAny({"with", "by"});
    return true;
  }

  bool nextIsAny(const std::vector<std::string>& ws) const {
    return pos_ + 1 < words_.size() && contains(ws, words_[pos_ + 1].text);
  }

  // A list is one n-ary union (unions flatten in the graph anyway), built without copies: a list of
  // thousands of operands is one node, not a left-deep chain copied at every link.
  nlohmann::json list() {
    nlohmann::json operands = nlohmann::json::array();
    previousHead_ = kNone;
    operands.push_back(meet());
    while (joinsList()) {
      previousHead_ = head_;  // "a cube and a sphere to its right": its = the cube
      nlohmann::json operand = meet();
      if (joinedByWith_ && acceptCutOut()) {
        pendingCut_ = std::move(operand);  // "X with Y cut out": expr() subtracts Y
        break;
      }
      operands.push_back(std::move(operand));
    }
    return operands.size() == 1 ? std::move(operands[0]) : node("union", std::move(operands));
  }

  nlohmann::json meet() {
    nlohmann::json operands = nlohmann::json::array();
    operands.push_back(item());
    while (at("intersected")) {
      ++pos_;
      expect("with");
      previousHead_ = head_;
      operands.push_back(item());
    }
    return operands.size() == 1 ? std::move(operands[0]) : node("intersection", std::move(operands));
  }

  [[noreturn]] void tooDeep() const {
    throw Error(errc::kLimitExceeded,
                "the query nests operations deeper than " + std::to_string(kMaxNesting) + " levels (at character " +
                    std::to_string(offset()) + ")",
                "text");
  }

  nlohmann::json item() {
    if (++depth_ > kMaxNesting) tooDeep();
    struct Leave {
      int& d;
      ~Leave() { --d; }
    } leave{depth_};
    if (accept("(")) {
      nlohmann::json inner = expr();
      if (!accept(")")) fail({"')'", "'minus'", "'and'", "'plus'", "'intersected with'"});
      return inner;  // head_: expr's (a single leaf in parentheses keeps its head)
    }
    const size_t save = pos_;
    acceptAny(queryArticles());
    const size_t groupFrom = offset();
    const char* group = collective();
    const size_t groupEnd = group ? words_[pos_ - 1].offset + words_[pos_ - 1].text.size() : 0;
    size_t n = numeral();
    if (group) n = std::max<size_t>(n, 2);  // "a stack of spheres": at least two
    if (n) {
      // numeral noun_phrase [ arrangement ]: that many copies of the part, united ("two balls",
      // "three spheres in a row", "a pair of cylinders"). An arrangement that says where they
      // stand places each copy against the one before it, as "a sphere beside a sphere" would:
      // beside it for a row ("in a row", "side by side"), on top of it for a stack ("stacked"),
      // so that three balls in a row are not a snowman. "together" and "touching" say nothing
      // of a direction.
      nlohmann::json first = leaf();
      const size_t one = leaves_.size() - 1;
      nlohmann::json operands = nlohmann::json::array();
      operands.push_back(std::move(first));
      for (size_t k = 1; k < n; ++k) {
        leaves_.push_back(leaves_[one]);
        operands.push_back(placeholder(leaves_.size() - 1));
      }
      const size_t from = offset();
      const char* direction = acceptArrangement();
      std::string words;
      if (direction) {
        const size_t end = words_[pos_ - 1].offset + words_[pos_ - 1].text.size();  // as relationWords ends
        words = text_.substr(from, end - from);
      } else if (group && *group) {
        direction = group;  // the collective noun's arrangement: "a stack of"
        words = text_.substr(groupFrom, groupEnd - groupFrom);
      }
      if (direction)
        for (size_t k = 1; k < n; ++k)
          leaves_[one + k].relation = CsgRelation{one + k - 1, *v_.direction(direction), std::nullopt, words};
      return node("union", std::move(operands));
    }
    if ((at("common") && nextIsAny({"part"})) || at("where") || (at("part") && nextIsAny({"where"}))) {
      // "the common part of X and Y", "(the part) where X and Y overlap": their intersection.
      const bool where = !at("common");
      pos_ += at("part") ? 2 : at("where") ? 1 : 2;
      if (!where) expect("of");
      nlohmann::json operands = nlohmann::json::array();
      previousHead_ = kNone;
      operands.push_back(item());
      if (!joinsList()) fail({"'and'", "','"});
      do {
        previousHead_ = head_;
        operands.push_back(item());
      } while (joinsList());
      if (where && !acceptAny({"overlap", "overlaps", "meet", "meets", "intersect", "intersects", "cross"}))
        fail({"'overlap'", "'meet'", "'intersect'"});
      return node("intersection", std::move(operands));
    }
    if (at("part") && nextIsAny({"of"})) {
      // "the part of X inside Y": their intersection.
      pos_ += 2;
      nlohmann::json operands = nlohmann::json::array();
      previousHead_ = kNone;
      operands.push_back(item());
      if (!acceptAny({"inside", "within", "in"})) fail({"'inside'", "'within'"});
      previousHead_ = kNone;
      operands.push_back(item());
      return node("intersection", std::move(operands));
    }
    if (at("union") || at("intersection") || at("difference")) {
      const std::string op = words_[pos_++].text;
      expect("of");
      nlohmann::json operands = nlohmann::json::array();
      previousHead_ = kNone;
      operands.push_back(item());
      if (op == "difference") {
        expect("and");
        previousHead_ = head_;
        operands.push_back(item());
        return node(op, std::move(operands));
      }
      if (!joinsList()) fail({"'and'", "','"});
      do {
        previousHead_ = head_;  // "the union of a cube and a sphere to its right": its = the cube
        operands.push_back(item());
      } while (joinsList());
      return node(op, std::move(operands));
    }
    pos_ = save;
    return relatedLeaf();
  }

  // noun_phrase [ relation ]: "a sphere on top of a cylinder" is the union of both, the sphere
  // placed against the cylinder; "a sphere to its right" is the sphere placed against the operand
  // before it (previousHead_). head_ is the subject leaf either way.
  nlohmann::json relatedLeaf() {
    // [ article ] "hollow" noun_phrase (hollow()): the hollowed part is the subject.
    const bool hollowed = atAny(kHollowWords) || (atAny(queryArticles()) && nextIsAny(kHollowWords));
    // [ article ] drilled noun_phrase (drilledPart()): the drilled part is the subject.
    const bool drilled =
        !hollowed && (atAny(kDrilledWords) || (atAny(queryArticles()) && nextIsAny(kDrilledWords)));
    std::string how;
    if (hollowed || drilled) {
      if (!atAny(hollowed ? kHollowWords : kDrilledWords)) ++pos_;
      how = words_[pos_++].text;
    }
    const size_t subjectLeaf = leaves_.size();  // the next leaf read, hollowed or not
    nlohmann::json subject = hollowed ? hollow(how) : drilled ? drilledPart(how) : leaf();
    // (A hollowed or drilled part is a difference of two leaves; copying its outer leaf alone would
    // make the second copy whole, so at both ends it stays one.)
    if (const int ends = endWords())
      return atEnds(std::move(subject), subjectLeaf, ends == 2 && !hollowed && !drilled);
    const size_t before = previousHead_;
    std::optional<RelationWords> words = relationWords();
    head_ = subjectLeaf;
    if (!words) return subject;
    CsgRelation relation{kNone, words->direction, words->distance, text_.substr(words->from, words->end - words->from)};
    if (!words->object) {
      if (before == kNone)
        throw Error(errc::kInvalidParameter,
                    "'" + relation.text + "' at character " + std::to_string(words->from) +
                        " places this part against the part before it, but none comes before it in its list; "
                        "name the other part, as in 'a sphere to the right of a cube'",
                    "text");
      relation.to = before;
      leaves_[subjectLeaf].relation = std::move(relation);
      head_ = subjectLeaf;
      return subject;
    }
    previousHead_ = kNone;
    const size_t objectAt = offset();
    nlohmann::json object = item();  // may be placed itself: "a cone on top of a cube on top of a box"
    if (head_ == kNone)
      throw Error(errc::kInvalidParameter,
                  "'" + relation.text + "' at character " + std::to_string(words->from) +
                      " places a part against one other part, but the words at character " + std::to_string(objectAt) +
                      " make an operation of several; name one part, as in 'a sphere on top of a cylinder'",
                  "text");
    relation.to = head_;
    leaves_[subjectLeaf].relation = std::move(relation);
    nlohmann::json operands = nlohmann::json::array();
    operands.push_back(std::move(subject));
    operands.push_back(std::move(object));
    nlohmann::json out = node("union", std::move(operands));
    head_ = subjectLeaf;
    return out;
  }

  // at_ends (header grammar) after a noun phrase: 1 for one end ("at its end", "on the end"), 2 for
  // both ("at both ends", "on each end", "at either end", "at its ends"), 0 when the words there
  // are none (pos_ unchanged).
  int endWords() {
    if (!atAny({"at", "on"}) || pos_ + 2 >= words_.size()) return 0;
    const std::string& a = words_[pos_ + 1].text;
    const std::string& b = words_[pos_ + 2].text;
    int ends = 0, used = 3;
    if (b == "end" && contains({"its", "the", "an"}, a)) ends = 1;
    else if (b == "end" && contains({"each", "either", "every"}, a)) ends = 2;
    else if (b == "ends" && contains({"its", "the", "both"}, a)) ends = 2;
    else if (a == "both" && contains({"its", "the"}, b) && pos_ + 3 < words_.size() && words_[pos_ + 3].text == "ends")
      ends = 2, used = 4;
    pos_ += ends ? used : 0;
    return ends;
  }

  // A noun phrase at the end (or both ends) of a part: the part before it in its list ("a plate
  // with a peg at its end"), or the object after "of" ("a ball at the end of a rod"). An end lies
  // along that part's long axis, which words do not place in world directions, so the union says
  // no direction: the parts alone. Both ends: two copies of the noun phrase, as "two balls" makes
  // them ("a stick with balls on both ends" is a stick and two balls).
  nlohmann::json atEnds(nlohmann::json subject, size_t subjectLeaf, bool two) {
    nlohmann::json operands = nlohmann::json::array();
    operands.push_back(std::move(subject));
    if (two) {
      leaves_.push_back(leaves_[subjectLeaf]);
      operands.push_back(placeholder(leaves_.size() - 1));
    }
    if (accept("of")) {
      if (accept("it")) {
        // the part before: nothing more to read
      } else {
        previousHead_ = kNone;
        operands.push_back(item());
      }
    }
    head_ = subjectLeaf;
    return operands.size() == 1 ? std::move(operands[0]) : node("union", std::move(operands));
  }

  struct RelationWords {
    Direction direction;
    std::optional<FuzzyNumber> distance;
    bool object = false;  // an object follows ("of a cube"); false: the operand before
    size_t from = 0, end = 0;  // characters of the words in text_
  };

  // relation (header grammar) after a noun phrase, or nothing (pos_ unchanged) when the words
  // there are no relation.
  std::optional<RelationWords> relationWords() {
    const size_t save = pos_;
    if (pos_ >= words_.size()) return std::nullopt;
    RelationWords r;
    r.from = words_[pos_].offset;
    r.distance = distanceWords();
    const Direction* d = nullptr;
    bool needsOf = false, mayHaveObject = false;
    std::string word;
    if (atAny({"to", "on", "at"}) && pos_ + 1 < words_.size() &&
        (words_[pos_ + 1].text == "its" || words_[pos_ + 1].text == "the") &&
        (d = directionWordAt(pos_ + 2, &word)) != nullptr) {
      // "to its right", "on the left side", "to the top right of ..."
      const bool its = words_[pos_ + 1].text == "its";
      pos_ += 2 + countWords(word);
      accept("side");
      if (!its && accept("of")) r.object = objectFollows();
    } else if (at("on") && pos_ + 1 < words_.size() && words_[pos_ + 1].text == "top" &&
               !(pos_ + 2 < words_.size() && words_[pos_ + 2].text == "of")) {
      d = v_.direction("top");  // "with a sphere on top"
      pos_ += 2;
    } else if ((d = directionWordAt(pos_, &word)) != nullptr) {
      pos_ += countWords(word);
      needsOf = d->word == word;   // a direction word: "right of a cube"
      mayHaveObject = !needsOf;    // a phrase: "above a cube", "on top of it", "above" (the one before)
      if (needsOf) {
        if (!accept("of")) {
          pos_ = save;
          return std::nullopt;
        }
        r.object = objectFollows();
      } else if (mayHaveObject) {
        r.object = objectFollows();
      }
    }
    if (!d) {
      pos_ = save;
      return std::nullopt;
    }
    r.direction = *d;
    r.end = words_[pos_ - 1].offset + words_[pos_ - 1].text.size();
    return r;
  }

  // After a relation's "of" or phrase: "it" (consumed: the operand before) or the start of an
  // item (true), else nothing (false: the operand before, "with a sphere above").
  bool objectFollows() {
    if (accept("it")) return false;
    if (pos_ >= words_.size()) return false;
    static const std::vector<std::string> kEnds = {",",        ")",      "and",    "plus",     "minus",  "without",
                                                   "with",     "united", "combined", "joined", "together",
                                                   "along",    "intersected", "drilled", "cut", "removed"};
    return !contains(kEnds, words_[pos_].text);
  }

  // distance = number_phrase [ "unit" | "units" ] | DISTANCE_WORD; nothing (pos_ unchanged) when
  // the words are none.
  std::optional<FuzzyNumber> distanceWords() {
    if (pos_ >= words_.size()) return std::nullopt;
    if (const FuzzyNumber* word = v_.distance(words_[pos_].text)) {
      ++pos_;
      return *word;
    }
    const size_t save = pos_;
    size_t n = 0;
    if (at("between") && isNumberAt(pos_ + 1) && pos_ + 3 < words_.size() && words_[pos_ + 2].text == "and" &&
        isNumberAt(pos_ + 3))
      n = 4;
    else if (atAny({"exactly", "about", "around", "approximately", "roughly"}) && isNumberAt(pos_ + 1))
      n = 2;
    else if (isNumberAt(pos_))
      n = 1;
    if (n == 0) return std::nullopt;
    std::string phrase;
    for (size_t i = 0; i < n; ++i) phrase += (i ? " " : "") + words_[pos_ + i].text;
    pos_ += n;
    try {
      FuzzyNumber d = parseNumberPhrase(phrase);
      if (!accept("units")) accept("unit");
      return d;
    } catch (const Error& e) {
      pos_ = save;
      throw Error(errc::kInvalidParameter,
                  "bad distance '" + phrase + "' at character " + std::to_string(words_[save].offset) + ": " + e.what(),
                  "text");
    }
  }

  bool isNumberAt(size_t i) const { return i < words_.size() && isNumberWord(words_[i].text); }

  // The longest direction word or phrase of the vocabulary at word i ("top right", "in front of").
  const Direction* directionWordAt(size_t i, std::string* which) const {
    const Direction* best = nullptr;
    size_t bestLength = 0;
    for (const std::string& phrase : v_.directionWords()) {
      const size_t n = countWords(phrase);
      if (n <= bestLength || i + n > words_.size()) continue;
      std::string joined;
      for (size_t k = 0; k < n; ++k) joined += (k ? " " : "") + words_[i + k].text;
      if (joined == phrase) {
        best = v_.direction(phrase);
        bestLength = n;
        *which = phrase;
      }
    }
    return best;
  }

  static size_t countWords(const std::string& phrase) {
    return size_t(std::count(phrase.begin(), phrase.end(), ' ')) + 1;
  }

  bool atAny(const std::vector<std::string>& ws) const { return pos_ < words_.size() && contains(ws, words_[pos_].text); }

  nlohmann::json leaf() {
    if (pos_ >= words_.size()) fail({"a noun phrase such as 'a slightly bent cylinder'", "'('", "'the union of'"});
    const size_t from = words_[pos_].offset;
    NounPhraseAt phrase = phrases_.at(from);  // the text tokenised once, not at every leaf
    while (pos_ < words_.size() && words_[pos_].offset < phrase.end) ++pos_;
    CsgQueryLeaf out;
    out.text = text_.substr(from, phrase.end - from);
    out.condition = std::move(phrase.query);
    leaves_.push_back(std::move(out));
    return placeholder(leaves_.size() - 1);
  }

  // "," [ "and" ] | "and" | "plus" | "united with" | "combined with" | "joined with" | "joined to" |
  // "together with" | "along with" before one more operand of a list.
  bool joinsList() {
    joinedByWith_ = false;
    if (accept(",")) {
      accept("and");
      return true;
    }
    if (accept("and") || accept("plus")) return true;
    for (const auto& [first, second] : kUnionPhrases)
      if (acceptPair(first, second)) return true;
    // "X with Y" is a union unless a hole follows (expr() subtracts it) or Y is "cut out" (list()).
    if (at("with") && !atHole()) {
      ++pos_;
      joinedByWith_ = true;
      return true;
    }
    return false;
  }

  // request: as the linguistic parser reads it (query_tokens.h).
  void skipRequest() {
    pos_ += query_tokens::requestLength(
        [this](size_t k) { return pos_ + k < words_.size() ? &words_[pos_ + k].text : nullptr; }, v_);
  }

  // lead_in = [ article ] GENERIC ( "which" | "that" ) ( "is" | "are" ) construction
  //         | [ [ article ] GENERIC ] made_of
  // GENERIC: a noun without conditions ("shape", "shapes", "something", "parts"); made_of: "made",
  // "composed", "built", "formed" or "consisting" with "of" or "from". "a shape which is the union
  // of ..." is the union; "shapes made of a cube and a sphere" the list (a union). Anything else
  // is no lead-in ("a shape and a sphere" stays a list of two leaves).
  void skipLeadIn() {
    const size_t save = pos_;
    acceptAny(queryArticles());
    const Noun* noun = pos_ < words_.size() ? v_.noun(words_[pos_].text) : nullptr;
    if (noun && noun->conditions.empty() && noun->params.is_null()) {
      ++pos_;
      if (at("where")) return;  // "a shape where a cube and a sphere overlap"
      if ((accept("which") || accept("that")) && acceptAny({"is", "are"})) {
        if (madeOf() || startsConstruction()) return;
      } else if (madeOf()) {
        return;
      }
    }
    pos_ = save;
    madeOf();  // "made of ..." without a noun; leaves pos_ alone otherwise
  }

  bool madeOf() {
    const size_t save = pos_;
    if (acceptAny({"made", "composed", "built", "formed", "consisting"}) && acceptAny({"of", "from"})) return true;
    pos_ = save;
    return false;
  }

  // [ article ] ( "union" | "intersection" | "difference" | "part" ) "of", or "(".
  bool startsConstruction() const {
    size_t i = pos_;
    if (i < words_.size() && contains(queryArticles(), words_[i].text)) ++i;
    if (i < words_.size() && words_[i].text == "(") return true;
    if (i < words_.size() && words_[i].text == "where") return true;
    if (i + 1 < words_.size() && words_[i].text == "part" && words_[i + 1].text == "where") return true;
    if (i + 2 < words_.size() && words_[i].text == "common" && words_[i + 1].text == "part" &&
        words_[i + 2].text == "of")
      return true;
    return i + 1 < words_.size() && words_[i + 1].text == "of" &&
           (words_[i].text == "union" || words_[i].text == "intersection" || words_[i].text == "difference" ||
            words_[i].text == "part");
  }

  // A count of copies at the current word: "two" ... "ten", 2 ... 10, "pair of" (after "a"),
  // when a noun phrase follows; 0 (nothing read) otherwise.
  size_t numeral() {
    if (pos_ >= words_.size()) return 0;
    if (words_[pos_].text == "pair" && nextIsAny({"of"})) {
      pos_ += 2;
      return 2;
    }
    static const std::vector<std::string> kNumerals = {"two", "three", "four", "five", "six",
                                                       "seven", "eight", "nine", "ten"};
    const std::string& w = words_[pos_].text;
    size_t n = 0;
    for (size_t i = 0; i < kNumerals.size(); ++i)
      if (w == kNumerals[i]) n = i + 2;
    if (n == 0 && w.size() <= 2 && std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      const int k = std::atoi(w.c_str());
      if (k >= 2 && k <= 10) n = static_cast<size_t>(k);
    }
    // "2 units above ..." or "3 x 2 x 1" are numbers of measures and distances, not counts.
    if (n == 0 || pos_ + 1 >= words_.size() || contains({"x", "by", "unit", "units"}, words_[pos_ + 1].text)) return 0;
    ++pos_;
    return n;
  }

  // collective = ( "stack" | "pile" | "tower" | "row" | "line" | "array" | "set" | "group" |
  // "cluster" ) , "of": copies of the noun phrase that follows (at least two), each placed as the
  // noun says against the one before it (on top of it for a stack, a pile and a tower; beside it
  // for a row, a line and an array; a set, a group or a cluster says no direction: ""). nullptr
  // (pos_ unchanged) when the words there are none.
  const char* collective() {
    if (!nextIsAny({"of"})) return nullptr;
    const char* direction = nullptr;
    if (atAny({"stack", "pile", "tower"})) direction = "top";
    else if (atAny({"row", "line", "array"})) direction = "side";
    else if (atAny({"set", "group", "cluster"})) direction = "";
    if (direction) pos_ += 2;
    return direction;
  }

  // The words of an arrangement after counted copies: "together", "joined together", "in a row",
  // "in a line", "lined up", "side by side", "touching [each other]", "next to each other",
  // "stacked [up]", after an optional "which are" and "joined".
  // Returns the vocabulary direction of each copy from the one before it ("side" for a row, "top"
  // for a stack), or nullptr where the words name none.
  const char* acceptArrangement() {
    const size_t start = pos_;
    // A lead-in: "which are", "that are", and a joining participle ("three balls which are
    // glued in line": glued is routed to joined before the parse).
    if (atAny({"which", "that"}) && nextIsAny({"are", "is"})) pos_ += 2;
    if (atAny({"which", "that"}) && nextIsAny({"touch", "touches"})) ++pos_;
    const bool joined = accept("joined");
    if (accept("together")) return nullptr;
    const size_t save = pos_;
    if (acceptPair("lined", "up")) return "side";
    if (accept("in")) {
      accept("a");
      if (accept("row") || accept("line")) return "side";
      pos_ = save;
    }
    if (acceptPair("side", "by") && accept("side")) return "side";
    pos_ = save;
    if (accept("touching")) {
      acceptPair("each", "other");
      return nullptr;
    }
    // The verb itself before "each other", as a writer in another language says it ("two ball
    // touch each other"), or in the present ("two balls that touch each other" reads its lead-in).
    if (atAny({"touch", "touches", "touched"}) && pos_ + 2 < words_.size() && words_[pos_ + 1].text == "each" &&
        words_[pos_ + 2].text == "other") {
      pos_ += 3;
      return nullptr;
    }
    if (acceptPair("next", "to") && acceptPair("each", "other")) return "side";
    pos_ = save;
    if (accept("stacked")) {
      accept("up");
      return "top";
    }
    if (!joined) pos_ = start;  // a lead-in with no arrangement after it is not read
    return nullptr;
  }

  bool acceptPair(const char* first, const char* second) {
    if (pos_ + 1 < words_.size() && words_[pos_].text == first && words_[pos_ + 1].text == second) {
      pos_ += 2;
      return true;
    }
    return false;
  }

  // {"op", "children"} taking the operands by move (a braced json list would copy them). An
  // operation has no head leaf (head_ = kNone) unless its caller says so.
  nlohmann::json node(const std::string& op, nlohmann::json operands) {
    head_ = kNone;
    nlohmann::json out = nlohmann::json::object();
    out["op"] = op;
    out["children"] = std::move(operands);
    return out;
  }

  bool at(const std::string& w) const { return pos_ < words_.size() && words_[pos_].text == w; }
  bool accept(const std::string& w) {
    if (!at(w)) return false;
    ++pos_;
    return true;
  }
  bool acceptAny(const std::vector<std::string>& ws) {
    for (const std::string& w : ws)
      if (accept(w)) return true;
    return false;
  }
  void expect(const std::string& w) {
    if (!accept(w)) fail({"'" + w + "'"});
  }
  size_t offset() const { return pos_ < words_.size() ? words_[pos_].offset : text_.size(); }

  [[noreturn]] void fail(const std::vector<std::string>& expected) const {
    std::string list;
    for (const std::string& e : expected) list += (list.empty() ? "" : ", ") + e;
    if (pos_ >= words_.size())
      throw Error(errc::kInvalidParameter,
                  "the query ends too early (character " + std::to_string(text_.size()) + "); expected " + list, "text");
    throw Error(errc::kInvalidParameter,
                "unexpected '" + quotedWord(words_[pos_].text) + "' at character " + std::to_string(words_[pos_].offset) +
                    "; expected " + list,
                "text");
  }

  static constexpr int kMaxNesting = 64;
  static constexpr size_t kNone = std::string::npos;
  const std::string owned_;  // the text with hollow words first (hollowWordsFirst)
  const std::string& text_;
  std::vector<Word> words_;
  std::vector<CsgQueryLeaf>& leaves_;
  NounPhraseReader phrases_;
  const Vocabulary& v_;
  nlohmann::json pendingCut_;   // "with Y cut out" met by list(), subtracted by expr()
  bool joinedByWith_ = false;   // the last joinsList() was a "with"
  size_t pos_ = 0;
  int depth_ = 0;
  size_t head_ = kNone;          // the leaf the last item is about (a leaf, or the subject of a relation)
  size_t previousHead_ = kNone;  // the head of the operand before the current one in its list
};

// The formula form: query/document/csg_text.h parses it; names that are no stored object are descriptions,
// read as noun phrases where they stand in the text (so errors give positions in `text`).
nlohmann::json formulaTree(const std::string& text, const Vocabulary& vocabulary, const ReferenceResolver& resolver,
                           std::vector<CsgQueryLeaf>& leaves) {
  std::vector<std::string> descriptionNames;
  const CsgNameKind kindOf = [&](const std::string& name, size_t column) -> std::string {
    if (resolver && resolver("part", name)) return "part";
    if (resolver && resolver("shape", name)) return "shape";
    const size_t from = column - 1 + (text[column - 1] == '"' ? 1 : 0);
    NounPhraseAt phrase = parseNounPhraseAt(text, from, from + name.size(), vocabulary);
    if (phrase.end < from + name.size())
      throw Error(errc::kInvalidParameter,
                  "'" + name + "' at character " + std::to_string(from) +
                      " is no stored part or shape, and as a description it ends at character " +
                      std::to_string(phrase.end) + "; expected one noun phrase such as 'very bent cylinder'",
                  "text");
    CsgQueryLeaf leaf;
    leaf.text = name;
    leaf.condition = std::move(phrase.query);
    leaves.push_back(std::move(leaf));
    descriptionNames.push_back(name);
    return "part";
  };
  nlohmann::json tree = parseCsgText(text, kindOf, "text").tree;
  // Description leaves, left to right as kindOf met them, become the placeholders 0, 1, ...
  size_t next = 0;
  std::function<void(nlohmann::json&)> replace = [&](nlohmann::json& node) {
    if (node.contains("children")) {
      for (nlohmann::json& c : node["children"]) replace(c);
    } else if (node.contains("part") && next < descriptionNames.size() && node["part"] == descriptionNames[next]) {
      node = placeholder(next++);
    }
  };
  replace(tree);
  return tree;
}

// Index of a placeholder leaf, or npos.
size_t placeholderIndex(const std::string& name) {
  if (name.compare(0, kPlaceholder.size(), kPlaceholder) != 0) return std::string::npos;
  return std::stoul(name.substr(kPlaceholder.size()));
}

// The graph of `doc` and the leaves: placeholders become `descriptions[k]`, parts stay parts.
CsgQuery graphOf(const std::string& form, const nlohmann::json& doc, const std::string& path, size_t maxNodes,
                 const ReferenceResolver& resolver, const std::vector<CsgQueryLeaf>& descriptions,
                 std::vector<size_t>* leafOfDescription = nullptr) {
  ShapeGraph g = shapeGraph(doc, path, maxNodes, resolver);
  CsgQuery q;
  q.form = form;
  q.graph = std::move(g.graph);
  std::vector<size_t> leafOf(descriptions.size(), std::string::npos);  // description -> graph leaf
  for (CsgGraphLeaf& leaf : g.leaves) {
    const size_t k = leaf.partId == 0 ? placeholderIndex(leaf.name) : std::string::npos;
    if (k != std::string::npos && k < descriptions.size()) {
      leafOf[k] = q.leaves.size();
      q.leaves.push_back(descriptions[k]);
      continue;
    }
    CsgQueryLeaf part;
    part.text = leaf.name;
    part.part = std::move(leaf.part);
    part.partId = leaf.partId;
    q.leaves.push_back(std::move(part));
  }
  // Relations name descriptions; the graph numbers its leaves in its own order.
  for (CsgQueryLeaf& leaf : q.leaves)
    if (leaf.relation) leaf.relation->to = leafOf.at(leaf.relation->to);
  if (leafOfDescription) *leafOfDescription = std::move(leafOf);
  return q;
}

// The query tree as "parsed" shows it: placeholders replaced by the description, with its
// relation ("to": the graph path of the other leaf).
nlohmann::json shownTree(nlohmann::json tree, const CsgQuery& query, const std::vector<size_t>& leafOf,
                         const std::vector<std::string>& paths) {
  if (tree.contains("children")) {
    for (nlohmann::json& c : tree["children"]) c = shownTree(std::move(c), query, leafOf, paths);
    return tree;
  }
  if (tree.contains("part") && tree["part"].is_object() && tree["part"].contains("name")) {
    const size_t k = placeholderIndex(tree["part"]["name"].get<std::string>());
    if (k < leafOf.size()) {
      const CsgQueryLeaf& leaf = query.leaves.at(leafOf[k]);
      nlohmann::json out = {{"text", leaf.text}, {"condition", toJson(*leaf.condition)["condition"]}};
      if (leaf.relation) {
        out["relation"] = {{"text", leaf.relation->text},
                           {"direction", leaf.relation->direction.word},
                           {"to", paths.at(leaf.relation->to)}};
        if (leaf.relation->distance) out["relation"]["distance"] = toJson(*leaf.relation->distance);
      }
      return out;
    }
  }
  return tree;
}

}  // namespace

CsgQuery parseCsgQuery(const std::string& text, const Vocabulary& vocabulary, const ReferenceResolver& resolver,
                       size_t maxNodes) {
  std::vector<CsgQueryLeaf> descriptions;
  const bool formula = isCsgFormula(text);
  // One lookup per reference: formulaTree asks for every name (as a part, then as a shape) and
  // graphOf asks again for the same names when it builds the leaves.
  const ReferenceResolver remembered = rememberingResolver(resolver);
  nlohmann::json tree =
      formula ? formulaTree(text, vocabulary, remembered, descriptions) : PhraseParser(text, vocabulary, descriptions).parse();
  const nlohmann::json doc = {{"kind", "shape"}, {"name", "query"}, {"tree", tree}};
  std::vector<size_t> leafOf;
  CsgQuery q = graphOf(formula ? "formula" : "phrase", doc, "", maxNodes, remembered, descriptions, &leafOf);
  q.tree = shownTree(std::move(tree), q, leafOf, q.graph.leafPaths());
  return q;
}

CsgQuery csgQueryFromDocument(const nlohmann::json& tree, size_t maxNodes, const ReferenceResolver& resolver) {
  const bool whole = tree.is_object() && tree.contains("kind");
  // A bare tree is wrapped at the request's root, so its paths read "tree.children[1]" as in the body.
  CsgQuery q = graphOf("tree", whole ? tree : nlohmann::json{{"kind", "shape"}, {"name", "query"}, {"tree", tree}},
                       whole ? "tree" : "", maxNodes, resolver, {});
  q.tree = whole && tree.contains("tree") ? tree["tree"] : tree;
  return q;
}

bool isCsgFormula(const std::string& text) {
  for (const Word& w : words(text)) {
    if (isNumberWord(w.text)) continue;  // "2.5e+32", "-3": a sign inside a number is no operator
    const std::string& t = w.text;
    for (size_t i = 0; i < t.size(); ++i) {
      const char c = t[i];
      if (c == '+' || c == '*' || c == '=' || c == '"') return true;
      if (c == '-' && !(i > 0 && isWordChar(t[i - 1]) && i + 1 < t.size() && isWordChar(t[i + 1]))) return true;
    }
  }
  return false;
}

const std::vector<std::string>& csgPhraseWords() {
  static const std::vector<std::string> words = [] {
    std::vector<std::string> w = kOperationWords;
    for (const auto& [a, b] : kUnionPhrases) w.insert(w.end(), {a, b});
    for (const auto& [a, b] : kCutOutPhrases) w.insert(w.end(), {a, b});
    // The other words the phrase parser reads (holes, relations, distances, lead-ins).
    w.insert(w.end(), {"drilled", "through", "by", "hole", "part", "inside", "within", "in", "of", "and", "with",
                       "on", "top", "to", "at", "the", "its", "it", "side", "between", "unit", "units", "which",
                       "that", "is", "are", "made", "composed", "built", "formed", "consisting", "from",
                       // counts of copies and their arrangement
                       "pair", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "together",
                       "row", "line", "lined", "touching", "touch", "touches", "touched", "each", "other", "next",
                       "stacked", "up", "hollow", "annular",
                       // ends of a part ("at its end", "on both ends")
                       "end", "ends", "both", "either", "every",
                       // parts with a hole ("a drilled block", "a cube which has a hole in the middle")
                       "bored", "pierced", "perforated", "holed", "has", "have", "middle", "center", "centre",
                       // collective nouns of copies ("a stack of spheres")
                       "stack", "pile", "tower", "array", "set", "group", "cluster",
                       // intersections in words
                       "common", "where", "overlap", "overlaps", "meet", "meets", "intersect", "intersects", "cross"});
    std::sort(w.begin(), w.end());
    w.erase(std::unique(w.begin(), w.end()), w.end());
    w.erase(std::remove(w.begin(), w.end(), std::string()), w.end());
    return w;
  }();
  return words;
}

bool isCsgQueryText(const std::string& text, const Vocabulary& vocabulary) {
  if (isCsgFormula(text)) return true;
  for (const Word& w : words(text))
    if (contains(kOperationWords, w.text)) return true;
  if (isLinguisticQuery(text, vocabulary)) return false;
  try {
    std::vector<CsgQueryLeaf> leaves;
    PhraseParser(text, vocabulary, leaves).parse();
    return true;
  } catch (const Error&) {
    return false;
  }
}

nlohmann::json toJson(const CsgQuery& query) {
  return {{"form", query.form},
          {"tree", query.tree},
          {"nodes", query.graph.size()},
          {"leaves", query.graph.leafCount}};
}

}  // namespace fsdb
