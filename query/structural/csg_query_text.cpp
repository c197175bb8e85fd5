// See query/structural/csg_query_text.h.
#include "query/structural/csg_query_text.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "geometry/core/error.h"
#include "query/document/csg_text.h"
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

bool contains(const std::vector<std::string>& list, const std::string& w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

struct Word {
  std::string text;  // lower case
  size_t offset;
};

// The words of the phrase form: runs of characters other than blanks and "(),", and those three.
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

// The phrase form: recursive descent over `words`, one function per production of the header; the
// leaves are noun phrases read by the linguistic parser from their first character on.
class PhraseParser {
 public:
  PhraseParser(const std::string& text, const Vocabulary& vocabulary, std::vector<CsgQueryLeaf>& leaves)
      : text_(text),
        words_(query_tokens::withoutFillers(words(text), vocabulary)),  // as the linguistic parser reads them
        leaves_(leaves),
        phrases_(text, vocabulary),
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
  //             | "with" hole | "with" meet cut_out      (cut_out: "cut out", "removed", ...)
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
      } else if (atHole()) {
        ++pos_;  // "with"
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
  bool atHole() const {
    if (!at("with")) return false;
    size_t i = pos_ + 1;
    if (i < words_.size() && contains(queryArticles(), words_[i].text)) ++i;
    if (i < words_.size() && words_[i].text == "hole") return true;
    return i + 1 < words_.size() && words_[i + 1].text == "hole" && !holeNoun(words_[i].text).empty();
  }

  // The noun a hole's shape word names: "cylinder-shaped" (any noun of the vocabulary with
  // "-shaped"), "cylindrical", "round" (a drilled hole), "spherical", "conical", "square",
  // "rectangular", "cubic"; "" for none.
  std::string holeNoun(const std::string& word) const {
    static const std::map<std::string, std::string> kForms = {
        {"cylindrical", "cylinder"}, {"round", "cylinder"},    {"circular", "cylinder"}, {"spherical", "sphere"},
        {"conical", "cone"},         {"square", "box"},        {"rectangular", "box"},   {"cubic", "cube"},
        {"pyramidal", "pyramid"}};
    const std::string suffix = "-shaped";
    if (word.size() > suffix.size() && word.compare(word.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string noun = word.substr(0, word.size() - suffix.size());
      return v_.noun(noun) ? noun : "";
    }
    auto it = kForms.find(word);
    return it == kForms.end() ? "" : it->second;
  }

  // hole = [ article ] [ shape word ] "hole", at atHole(): a description leaf of the noun its
  // shape word names (a cylinder when none: a drilled hole), with the words as written.
  nlohmann::json hole() {
    const size_t from = words_[pos_].offset;
    acceptAny(queryArticles());
    std::string noun = "cylinder";
    if (!at("hole")) noun = holeNoun(words_[pos_++].text);
    const size_t end = words_[pos_].offset + words_[pos_].text.size();
    ++pos_;  // "hole"
    CsgQueryLeaf out;
    out.text = text_.substr(from, end - from);
    out.condition = parseNounPhraseAt("a " + noun, 0, std::string::npos, v_).query;
    leaves_.push_back(std::move(out));
    return placeholder(leaves_.size() - 1);
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
    operands.push_back(meet());
    while (joinsList()) {
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
      return inner;
    }
    const size_t save = pos_;
    acceptAny(queryArticles());
    if (at("part") && nextIsAny({"of"})) {
      // "the part of X inside Y": their intersection.
      pos_ += 2;
      nlohmann::json operands = nlohmann::json::array();
      operands.push_back(item());
      if (!acceptAny({"inside", "within", "in"})) fail({"'inside'", "'within'"});
      operands.push_back(item());
      return node("intersection", std::move(operands));
    }
    if (at("union") || at("intersection") || at("difference")) {
      const std::string op = words_[pos_++].text;
      expect("of");
      nlohmann::json operands = nlohmann::json::array();
      operands.push_back(item());
      if (op == "difference") {
        expect("and");
        operands.push_back(item());
        return node(op, std::move(operands));
      }
      if (!joinsList()) fail({"'and'", "','"});
      do operands.push_back(item());
      while (joinsList());
      return node(op, std::move(operands));
    }
    pos_ = save;
    return leaf();
  }

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

  // [ article ] ( "union" | "intersection" | "difference" ) "of", or "(".
  bool startsConstruction() const {
    size_t i = pos_;
    if (i < words_.size() && contains(queryArticles(), words_[i].text)) ++i;
    if (i < words_.size() && words_[i].text == "(") return true;
    return i + 1 < words_.size() && words_[i + 1].text == "of" &&
           (words_[i].text == "union" || words_[i].text == "intersection" || words_[i].text == "difference");
  }

  bool acceptPair(const char* first, const char* second) {
    if (pos_ + 1 < words_.size() && words_[pos_].text == first && words_[pos_ + 1].text == second) {
      pos_ += 2;
      return true;
    }
    return false;
  }

  // {"op", "children"} taking the operands by move (a braced json list would copy them).
  static nlohmann::json node(const std::string& op, nlohmann::json operands) {
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
                "unexpected '" + words_[pos_].text + "' at character " + std::to_string(words_[pos_].offset) +
                    "; expected " + list,
                "text");
  }

  static constexpr int kMaxNesting = 64;
  const std::string& text_;
  std::vector<Word> words_;
  std::vector<CsgQueryLeaf>& leaves_;
  NounPhraseReader phrases_;
  const Vocabulary& v_;
  nlohmann::json pendingCut_;   // "with Y cut out" met by list(), subtracted by expr()
  bool joinedByWith_ = false;   // the last joinsList() was a "with"
  size_t pos_ = 0;
  int depth_ = 0;
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
                 const ReferenceResolver& resolver, const std::vector<CsgQueryLeaf>& descriptions) {
  ShapeGraph g = shapeGraph(doc, path, maxNodes, resolver);
  CsgQuery q;
  q.form = form;
  q.graph = std::move(g.graph);
  for (CsgGraphLeaf& leaf : g.leaves) {
    const size_t k = leaf.partId == 0 ? placeholderIndex(leaf.name) : std::string::npos;
    if (k != std::string::npos && k < descriptions.size()) {
      q.leaves.push_back(descriptions[k]);
      continue;
    }
    CsgQueryLeaf part;
    part.text = leaf.name;
    part.part = std::move(leaf.part);
    part.partId = leaf.partId;
    q.leaves.push_back(std::move(part));
  }
  return q;
}

// The query tree as "parsed" shows it: placeholders replaced by the description.
nlohmann::json shownTree(nlohmann::json tree, const std::vector<CsgQueryLeaf>& descriptions) {
  if (tree.contains("children")) {
    for (nlohmann::json& c : tree["children"]) c = shownTree(std::move(c), descriptions);
    return tree;
  }
  if (tree.contains("part") && tree["part"].is_object() && tree["part"].contains("name")) {
    const size_t k = placeholderIndex(tree["part"]["name"].get<std::string>());
    if (k < descriptions.size())
      return {{"text", descriptions[k].text}, {"condition", toJson(*descriptions[k].condition)["condition"]}};
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
  CsgQuery q = graphOf(formula ? "formula" : "phrase", doc, "", maxNodes, remembered, descriptions);
  q.tree = shownTree(std::move(tree), descriptions);
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
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '+' || c == '*' || c == '=' || c == '"') return true;
    if (c == '-' && !(i > 0 && isWordChar(text[i - 1]) && i + 1 < text.size() && isWordChar(text[i + 1]))) return true;
  }
  return false;
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
