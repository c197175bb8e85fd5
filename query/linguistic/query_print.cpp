// See query/linguistic/query_print.h.
#include "query/linguistic/query_print.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "query/json/fuzzy_json.h"
#include "query/json/number_phrases.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"

namespace fsdb {
namespace {

using Kind = QueryCondition::Kind;

[[noreturn]] void unprintable(const std::string& what) {
  throw Error(errc::kInvalidParameter, "no words of the vocabulary say " + what, "query");
}

std::string firstWord(const std::string& text) { return text.substr(0, text.find(' ')); }

// A number as query text: formatNumber's shortest form without the '+' of its exponent (2.5e32,
// not 2.5e+32), which both parsers read and which is shorter.
std::string numberText(double x) {
  std::string text = formatNumber(x);
  const size_t plus = text.find("e+");
  if (plus != std::string::npos) text.erase(plus + 1, 1);
  return text;
}

// Words are read in any case (query_tokens.h lower-cases them); a condition's text keeps the case
// the user wrote, so it is compared and printed lower-cased.
std::string lowerCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// A measure's extent as the words that read back to it (linguistic_query.h: a plain N is within
// 10 % of N, so a crisp extent is "exactly N").
// "about N" or "between A and B" when that number phrase is exactly `d`, else "".
std::string fuzzyNumberPhrase(const FuzzyNumber& d) {
  const Interval core = d.core(), support = d.support();
  const std::string about = "about " + numberText(core.lo);
  if (core.lo == core.hi && parseNumberPhrase(about) == d) return about;
  if (core.lo == support.lo && core.hi == support.hi) {
    const std::string between = "between " + numberText(core.lo) + " and " + numberText(core.hi);
    if (parseNumberPhrase(between) == d) return between;
  }
  return "";
}

bool measurePrintable(const FuzzyNumber& e) {
  const Interval core = e.core();
  return e.isCrisp() || (core.lo == core.hi && e == FuzzyNumber::triangular(0.9 * core.lo, core.lo, 1.1 * core.lo)) ||
         !fuzzyNumberPhrase(e).empty();
}

std::string measureText(const FuzzyNumber& e) {
  const Interval core = e.core();
  if (e.isCrisp()) return "exactly " + numberText(core.lo);
  if (core.lo == core.hi && e == FuzzyNumber::triangular(0.9 * core.lo, core.lo, 1.1 * core.lo)) return numberText(core.lo);
  const std::string phrase = fuzzyNumberPhrase(e);
  if (phrase.empty()) unprintable("the measure " + toJson(e).dump());
  return phrase;
}

std::string measureWord(const std::string& descriptor) {
  if (descriptor == "length") return "long";
  if (descriptor == "width") return "across";
  if (descriptor == "thickness") return "thick";
  if (descriptor == "height") return "tall";
  unprintable("a measure of " + descriptor);
}

class Printer {
 public:
  explicit Printer(const Vocabulary& v) : v_(v) {}

  // [ intensity ] adjective [ section ]: the words as written when they say it (a synonym stays
  // itself), else the first that do; or a descriptor degree as written.
  std::string leaf(const QueryCondition& c) const {
    if (c.measure) {
      // A radius doubled may be no number phrase of the width ("radius about 0.3" is
      // tri(0.4, 0.6, 0.8)); halved back (exactly, in binary) it reads as a radius again.
      if (c.descriptor == "width" && !measurePrintable(*c.measure)) return measureText(scale(*c.measure, 0.5)) + " in radius";
      return measureText(*c.measure) + " " + (c.axialLength ? "long" : measureWord(c.descriptor));
    }
    const std::string text = lowerCase(c.text);
    if (descriptorIndex(firstWord(text)) >= 0 && firstWord(text) == c.descriptor) return text;
    // A part's edges: the words as written ("rounded edges", or "rounded" before a square noun,
    // which its noun phrase turns the same way again).
    if (c.edges != QueryCondition::Edges::kNone) return text.rfind("a ", 0) == 0 ? text.substr(2) : text.rfind("an ", 0) == 0 ? text.substr(3) : text;
    std::string first;
    bool firstIsMiddle = false, firstOwn = false;
    for (const std::string& word : v_.adjectiveWords()) {
      const Adjective& a = *v_.adjective(word);
      const std::string* section = v_.sectionDescriptor(a.descriptor);
      const bool whole = a.descriptor == c.descriptor;
      const bool ofSection = section && *section == c.descriptor && !v_.sectionWords().empty();
      if (!whole && !ofSection) continue;
      const auto matches = [&](const FuzzyNumber& set) { return (a.lowPole ? mirroredDegrees(set) : set) == c.set; };
      std::vector<std::string> intensities;
      if (v_.plainSet(a) == c.set) intensities.push_back("");
      // The terms before their synonyms: "bent a lot" reads back as very bent, not highly bent.
      for (const std::vector<std::string>* words : {&v_.intensityOrder(), &v_.intensityWords()})
        for (const std::string& intensity : *words)
          if (matches(*v_.intensity(intensity))) intensities.push_back(intensity + " ");
      for (const std::string& intensity : intensities) {
        const std::string words = intensity + word;
        if (!ofSection) {
          if (words == text) return words;
          // A pole's adjective before a middle's ("very tapered" read back as "very narrowing",
          // not "very blunt", whose own set is a middle of taperness).
          // And the descriptor's own word before its synonyms: "very twisted" reads back as
          // very twisted (twistness), not very helical.
          const bool own = ownWord(word, c.descriptor);
          if (first.empty() || (firstIsMiddle && !a.set) || (own && !firstOwn && firstIsMiddle == a.set.has_value())) {
            first = words;
            firstIsMiddle = a.set.has_value();
            firstOwn = own;
          }
          continue;
        }
        for (const std::string& section : v_.sectionWords())
          for (const char* article : {"", "a ", "an "})
            if (article + words + " " + section == text) return words + " " + section;
        // An outline adjective as written turned onto a flat noun's section ("a round plate"):
        // only its noun phrase turns it, so the same words next to the same noun read the same.
        if (a.outline && words == text) return words;
        if (first.empty()) first = words + " " + v_.sectionWords().front();
      }
    }
    if (first.empty()) unprintable("the condition on " + c.descriptor + " of '" + c.text + "'");
    return first;
  }

  // Whether `word` is the word a descriptor is named after ("twisted" of twistness, "tapered"
  // and "tapering" of taperness): the descriptor's stem before "ness" begins it.
  static bool ownWord(const std::string& word, const std::string& descriptor) {
    const std::string ness = "ness";
    if (descriptor.size() <= ness.size() || descriptor.compare(descriptor.size() - ness.size(), ness.size(), ness) != 0)
      return false;
    const std::string stem = descriptor.substr(0, descriptor.size() - ness.size());
    return word.compare(0, stem.size(), stem) == 0;
  }

  std::string operand(const QueryCondition& c) const {
    return c.kind == Kind::kDescriptor ? leaf(c) : "(" + condition(c) + ")";
  }

  std::string condition(const QueryCondition& c) const {
    switch (c.kind) {
      case Kind::kDescriptor: return leaf(c);
      case Kind::kNot: return "not " + operand(c.children.at(0));
      case Kind::kAnd:
      case Kind::kOr: {
        if (c.children.empty()) unprintable("'anything' as a condition");
        std::string out;
        for (const QueryCondition& child : c.children)
          out += (out.empty() ? "" : c.kind == Kind::kAnd ? " and " : " or ") + operand(child);
        return out;
      }
      case Kind::kRelation: break;
    }
    unprintable("a relation inside a condition");
  }

  // "a" [ modifiers ] noun [ "that is" clause ]
  std::string nounPhrase(const QueryCondition& root, const std::string& subject, const std::string& article) const {
    std::vector<const QueryCondition*> parts;
    if (root.nounPhrase) {
      for (const QueryCondition& c : root.children) parts.push_back(&c);
    } else {
      parts.push_back(&root);
    }
    size_t nounAt = parts.size();
    for (size_t i = 0; i < parts.size(); ++i)
      if (!parts[i]->noun.empty()) nounAt = i;
    std::string noun = subject == "part" ? "part" : "shape";
    const QueryCondition* modifiers = nullptr;
    const QueryCondition* clause = nullptr;
    if (nounAt < parts.size()) {
      noun = parts[nounAt]->noun;
      // A noun an adjective named on a part ("a part that is cylindrical": a cylinder) is printed
      // as that adjective before "part", which reads back the same.
      const Adjective* named = v_.adjective(parts[nounAt]->text);
      if (subject == "part" && named && !named->shapeOf.empty()) noun = parts[nounAt]->text + " part";
      if (nounAt > 1 || parts.size() - nounAt > 2) unprintable("a noun phrase of more than three parts");
      if (nounAt == 1) modifiers = parts[0];
      if (nounAt + 1 < parts.size()) clause = parts[nounAt + 1];
    } else {
      // No noun conditions: one condition is the clause ("a shape that is bent"), two are the
      // modifiers and the clause; none ("anything") is the bare noun.
      if (parts.size() > 2) unprintable("a noun phrase of more than two conditions");
      const bool anything = parts.size() == 1 && parts[0]->kind == Kind::kAnd && parts[0]->children.empty();
      if (parts.size() == 1 && !anything) clause = parts[0];
      if (parts.size() == 2) {
        modifiers = parts[0];
        clause = parts[1];
      }
    }
    std::string out = article + " ";
    if (modifiers) out += modifierText(*modifiers) + " ";
    out += noun;
    // Edges named by an edge word ("round edges") read better after "with" than "that is".
    const bool namedEdges = clause && clause->edges == QueryCondition::Edges::kNamed;
    if (clause) out += (namedEdges ? " with " : " that is ") + condition(*clause);
    return out;
  }

 private:
  // Before a noun, an "or" or a "not" is one parenthesised condition, so the noun ends it.
  std::string modifierText(const QueryCondition& c) const {
    return c.kind == Kind::kAnd || c.kind == Kind::kDescriptor ? condition(c) : "(" + condition(c) + ")";
  }

  const Vocabulary& v_;
};

}  // namespace

std::string distanceText(const FuzzyNumber& d, const Vocabulary& vocabulary) {
  for (const std::string& word : vocabulary.distanceWords())
    if (*vocabulary.distance(word) == d) return word;
  if (d.isCrisp()) return numberText(d.core().lo);
  const std::string phrase = fuzzyNumberPhrase(d);
  if (phrase.empty()) unprintable("the distance " + toJson(d).dump());
  return phrase;
}

std::string nounPhraseText(const LinguisticQuery& phrase, const Vocabulary& vocabulary, const std::string& article) {
  return Printer(vocabulary).nounPhrase(phrase.root, phrase.subject, article);
}

std::string linguisticQueryText(const LinguisticQuery& query, const Vocabulary& vocabulary) {
  const Printer p(vocabulary);
  std::string out = "find ";
  if (query.root.kind == Kind::kRelation) {
    const QueryCondition& r = query.root;
    out += p.nounPhrase(r.children.at(0), "any", "a");
    if (r.distance) out += " " + distanceText(*r.distance, vocabulary);
    out += " to the " + r.direction + " of " + p.nounPhrase(r.children.at(1), "any", "a");
  } else {
    out += p.nounPhrase(query.root, query.subject, "a");
  }
  if (query.atLeast > 0) out += " at least " + numberText(query.atLeast);
  if (query.aggregation != "min") out += " using " + query.aggregation;
  return out;
}

}  // namespace fsdb
