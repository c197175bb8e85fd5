// Property: texts generated at random from both grammars (schema/query_grammar.ebnf and
// schema/csg_query_grammar.ebnf: requests, conditions with and / or / not / parentheses /
// degrees / sections, nouns and pronouns, relative clauses, relations with distances and every
// direction form, thresholds and aggregations; CSG operations in every phrasing, nesting,
// spatial relations) parse; each prints back (query/linguistic/query_print.h,
// query/structural/csg_query_print.h) to a text that parses to an equivalent query, and a
// printed text prints as itself. 1000 texts of each grammar, fixed seeds.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "geometry/core/error.h"
#include "query/linguistic/query_print.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_print.h"
#include "tests/testing/query_shapes.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

int uniform(std::mt19937& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
bool chance(std::mt19937& rng, int percent) { return uniform(rng, 0, 99) < percent; }
template <typename T>
const T& pick(std::mt19937& rng, const std::vector<T>& list) {
  return list[size_t(uniform(rng, 0, int(list.size()) - 1))];
}

const std::vector<std::string> kNouns = {"cylinder", "cylinders", "box",   "sphere",         "ball",
                                         "rod",      "cone",      "plate", "double pyramid", "pyramid",
                                         "disc",     "block",     "shape", "part",           "object"};
const std::vector<std::string> kSections = {"traverse section", "cross-section", "cross section", "section"};
const std::vector<std::string> kDegrees = {"at least 0.5", "at most 0.2",         "about 0.3",
                                           "0.4",          "between 0.2 and 0.6", "is about 0.7"};
const std::vector<std::string> kDistances = {"about 3", "about 2 units", "3",   "1.5 units", "between 2 and 4",
                                             "close",   "near",          "far", "touching"};

// negation = "not" negation | "(" condition ")" | descriptor degree | [intensity] adjective [section]
std::string negation(std::mt19937& rng, int depth) {
  const int form = uniform(rng, 0, depth > 1 ? 5 : 9);
  if (form == 6) return "not " + negation(rng, depth + 1);
  if (form >= 7) {
    std::string inner = negation(rng, depth + 1) + pick(rng, std::vector<std::string>{" and ", " or ", ", "}) +
                        negation(rng, depth + 1);
    return "(" + inner + ")";
  }
  if (form == 5) return pick(rng, descriptorNames()) + " " + pick(rng, kDegrees);
  std::string out;
  if (chance(rng, 50)) out += pick(rng, v().intensityWords()) + " ";
  if (form == 4) {  // a section: an adjective of squariness or roundness
    out += pick(rng, std::vector<std::string>{"square", "squarish", "boxy", "round", "rounded", "circular"});
    return out + " " + pick(rng, kSections);
  }
  return out + pick(rng, v().adjectiveWords());
}

// condition = conjunct { "or" conjunct }; conjunct = negation { ["and" | ","] negation }
std::string condition(std::mt19937& rng) {
  std::string out = negation(rng, 0);
  for (int i = uniform(rng, 0, 2); i > 0; --i)
    out += pick(rng, std::vector<std::string>{" and ", " or ", ", "}) + negation(rng, 0);
  return out;
}

// noun_phrase = [article] [condition] noun [clause]; pronouns take their condition after them.
std::string nounPhrase(std::mt19937& rng) {
  const std::string article = pick(rng, std::vector<std::string>{"a ", "the ", "some ", ""});
  if (chance(rng, 15)) return article + pick(rng, std::vector<std::string>{"something ", "anything "}) + condition(rng);
  std::string noun = pick(rng, kNouns);
  std::string out = article;
  if (chance(rng, 60)) out += condition(rng) + " ";
  if (noun == "box" && article.empty() && out.empty()) noun = "boxes";  // a bare noun
  out += noun;
  if (chance(rng, 35))
    out += pick(rng, std::vector<std::string>{" that is ", " which are ", " with ", " that has "}) + condition(rng);
  return out;
}

std::string relationWords(std::mt19937& rng) {
  std::string out;
  if (chance(rng, 50)) out += pick(rng, kDistances) + " ";
  const int form = uniform(rng, 0, 2);
  if (form == 0) return out + "to the " + pick(rng, v().directionWords()) + " of ";  // phrases read too
  if (form == 1)
    return out + pick(rng, std::vector<std::string>{"right", "left", "top right", "bottom front"}) + " of ";
  return out + pick(rng, std::vector<std::string>{"above", "below", "on top of", "behind", "in front of", "under"}) +
         " ";
}

std::string linguisticText(std::mt19937& rng) {
  std::vector<std::string> requests = v().requestPhrases();
  requests.push_back("");
  std::string out = pick(rng, requests);
  if (!out.empty()) out += " ";
  out += nounPhrase(rng);
  if (chance(rng, 30)) out += " " + relationWords(rng) + nounPhrase(rng);
  if (chance(rng, 20)) out += " at least 0." + std::to_string(uniform(rng, 1, 9));
  if (chance(rng, 20)) out += " using " + pick(rng, std::vector<std::string>{"min", "product", "mean"});
  return out;
}

TEST(QueryPrintProperty, LinguisticTextsPrintBackToTheSameQuery) {
  std::mt19937 rng(2026);
  int parsed = 0;
  for (int k = 0; k < 1000; ++k) {
    const std::string text = linguisticText(rng);
    LinguisticQuery q;
    try {
      q = parseLinguisticQuery(text, v());
    } catch (const Error&) {
      continue;  // a generated text the grammar does not read (counted below)
    }
    ++parsed;
    const std::string printed = linguisticQueryText(q, v());
    LinguisticQuery again;
    ASSERT_NO_THROW(again = parseLinguisticQuery(printed, v())) << text << "\n -> " << printed;
    EXPECT_EQ(testing::queryMeaning(again), testing::queryMeaning(q)) << text << "\n -> " << printed;
    EXPECT_EQ(linguisticQueryText(again, v()), printed) << text;
  }
  // Nearly every generated text reads (a few word sequences are ambiguous: "a bent and a ..."):
  EXPECT_GE(parsed, 950);
}

// An item of the phrase form and whether it has a head (a leaf, or a leaf placed against another:
// what "to its right" after it points at).
struct Item {
  std::string text;
  bool head = false;
};

Item csgItem(std::mt19937& rng, int depth);

std::string csgLeaf(std::mt19937& rng, const std::string& article = "") {
  std::string out = article.empty() ? pick(rng, std::vector<std::string>{"a ", "the "}) : article;
  if (chance(rng, 50)) out += negation(rng, 1) + " ";
  return out + pick(rng, std::vector<std::string>{"cylinder", "box", "sphere", "rod", "cone", "pyramid", "cube"});
}

// An operand of a list: an operation in parentheses (a "the union of" list takes every item
// after it), and "to its DIRECTION" only after an operand with a head.
std::string csgOperands(std::mt19937& rng, int depth, const std::string& joiner) {
  const auto operand = [&](bool* head) {
    const Item item = csgItem(rng, depth + 1);
    *head = item.head;
    return item.head ? item.text : "(" + item.text + ")";
  };
  bool head = false;
  std::string out = operand(&head);
  for (int i = uniform(rng, 1, 2); i > 0; --i) {
    const bool before = head;
    out += joiner + operand(&head);
    if (before && head && chance(rng, 30)) {
      const std::string leaf = csgLeaf(rng);
      out += joiner + leaf + " " + pick(rng, std::vector<std::string>{"about 2 units ", "", "close "}) + "to its " +
             pick(rng, std::vector<std::string>{"right", "left", "top", "top right", "front"});
    }
  }
  return out;
}

Item csgItem(std::mt19937& rng, int depth) {
  const int form = uniform(rng, 0, depth >= 2 ? 1 : 7);
  const auto wrapped = [&](const Item& i) { return i.head ? i.text : "(" + i.text + ")"; };
  switch (form) {
    case 0: return {csgLeaf(rng), true};
    case 1: return {csgLeaf(rng) + " " + relationWords(rng) + csgLeaf(rng), true};
    case 2: return {"the union of " + csgOperands(rng, depth, pick(rng, std::vector<std::string>{" and ", ", "}))};
    case 3: return {"the intersection of " + csgOperands(rng, depth, " and ")};
    case 4:
      return {"the difference of " + wrapped(csgItem(rng, depth + 1)) + " and " + wrapped(csgItem(rng, depth + 1))};
    case 5: return {"the part of " + csgLeaf(rng) + " inside " + wrapped(csgItem(rng, depth + 1))};
    case 6:
      return {
          "(" + wrapped(csgItem(rng, depth + 1)) +
          pick(rng, std::vector<std::string>{" minus ", " without ", " plus ", " united with ", " intersected with "}) +
          wrapped(csgItem(rng, depth + 1)) + ")"};
    default: return {"(" + csgLeaf(rng) + " with " + csgLeaf(rng, "the ") + " on top)"};
  }
}

TEST(QueryPrintProperty, CsgTextsPrintBackToTheSameQuery) {
  std::mt19937 rng(1202);
  int parsed = 0;
  for (int k = 0; k < 1000; ++k) {
    const Item item = csgItem(rng, 0);
    std::string text = item.text;
    // A lead-in names a construction ("a shape which is the union of ..."), not a leaf.
    if (!item.head && chance(rng, 20)) text = "a shape which is " + text;
    if (chance(rng, 30)) text = pick(rng, std::vector<std::string>{"find ", "show me "}) + text;
    CsgQuery q;
    try {
      q = parseCsgQuery(text, v(), {}, 1000);
    } catch (const Error& e) {
      if (std::getenv("FSDB_SHOW_UNREAD")) std::fprintf(stderr, "%s\n  %s\n", text.c_str(), e.what());
      continue;
    }
    ++parsed;
    const std::string printed = csgQueryText(q, v());
    CsgQuery again;
    ASSERT_NO_THROW(again = parseCsgQuery(printed, v(), {}, 1000)) << text << "\n -> " << printed;
    EXPECT_EQ(testing::csgMeaning(again), testing::csgMeaning(q)) << text << "\n -> " << printed;
    EXPECT_EQ(csgQueryText(again, v()), printed) << text;
  }
  EXPECT_GE(parsed, 990);
}

}  // namespace
}  // namespace fsdb
