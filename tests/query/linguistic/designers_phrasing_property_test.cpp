// Property: texts generated from the designers' side of the grammars (requests, fillers anywhere,
// bare descriptions, pronouns, nouns with their conditions; for CSG, lead-ins and every union
// joiner) parse to the same query as the grammar's own phrasing built alongside them. 500 random
// texts of each kind, fixed seeds.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"
#include "query/structural/csg_query_text.h"
#include "tests/testing/query_shapes.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

nlohmann::json meaning(const std::string& text) { return testing::queryMeaning(parseLinguisticQuery(text, v())); }

template <typename T>
const T& pick(std::mt19937& rng, const std::vector<T>& list) {
  return list[std::uniform_int_distribution<size_t>(0, list.size() - 1)(rng)];
}

// The words of `text` with fillers put between random pairs of them.
std::string withFillers(std::mt19937& rng, const std::string& text) {
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    if (!out.empty()) out += ' ';
    if (std::uniform_int_distribution<int>(0, 5)(rng) == 0) out += pick(rng, std::vector<std::string>{"please", "kindly"}) + " ";
    out += text.substr(start, end - start);
    start = end + 1;
  }
  return out;
}

// One to three conditions: [intensity] adjective, joined by ", ", " and " or a blank.
std::string conditions(std::mt19937& rng) {
  const auto& intensities = v().intensityWords();
  const auto& adjectives = v().adjectiveWords();
  std::string out;
  const int n = std::uniform_int_distribution<int>(1, 3)(rng);
  for (int i = 0; i < n; ++i) {
    if (i > 0) out += pick(rng, std::vector<std::string>{", ", " and ", " "});
    if (std::uniform_int_distribution<int>(0, 1)(rng)) out += pick(rng, intensities) + " ";
    out += pick(rng, adjectives);
  }
  return out;
}

TEST(DesignersPhrasingProperty, LinguisticTextsMeanTheirGrammarForm) {
  std::mt19937 rng(20261202);
  std::vector<std::string> requests = v().requestPhrases();
  requests.push_back("");
  const std::vector<std::string> nouns = {"cylinder", "box", "sphere", "rod", "cone", "plate", "double pyramid"};
  for (int k = 0; k < 500; ++k) {
    const std::string conds = conditions(rng);
    const std::string request = pick(rng, requests);
    std::string said, grammar;
    switch (k % 3) {
      case 0:  // a bare description
        said = conds;
        grammar = "find shapes that are " + conds;
        break;
      case 1:  // a pronoun with its adjectives after it
        said = pick(rng, std::vector<std::string>{"something ", "anything "}) + conds;
        grammar = "find shapes that are " + conds;
        break;
      default: {  // a noun with its adjectives before it
        const std::string noun = pick(rng, nouns);
        said = "a " + conds + " " + noun;
        grammar = "find a " + conds + " " + noun;
      }
    }
    said = withFillers(rng, (request.empty() ? "" : request + " ") + said);
    ASSERT_NO_THROW(meaning(said)) << said;
    EXPECT_EQ(meaning(said), meaning(grammar)) << said << "  vs  " << grammar;
  }
}

TEST(DesignersPhrasingProperty, CsgTextsMeanTheirGrammarForm) {
  std::mt19937 rng(7);
  const std::vector<std::string> leaves = {"a very bent cylinder", "a very sharp pyramid", "a sphere", "a round box",
                                           "a slightly twisted rod", "a cone"};
  const std::vector<std::string> joiners = {" and ", ", ", " plus ", " united with ", " combined with ", " joined with ",
                                            " joined to ", " together with ", " along with ", " with "};
  const std::vector<std::string> leadIns = {"", "a shape which is made of ", "shapes made of ", "made of ",
                                            "something composed of ", "a part that is made of ", "objects built from "};
  std::vector<std::string> requests = v().requestPhrases();
  requests.push_back("");
  for (int k = 0; k < 500; ++k) {
    const int n = std::uniform_int_distribution<int>(2, 4)(rng);
    std::string said, expected = "union(";
    for (int i = 0; i < n; ++i) {
      const std::string leaf = pick(rng, leaves);
      if (i > 0) said += pick(rng, joiners);
      said += leaf;
      expected += (i ? ", '" : "'") + leaf + "'";
    }
    expected += ")";
    const std::string request = pick(rng, requests);
    said = (request.empty() ? "" : request + " ") + pick(rng, leadIns) + said;
    // A difference at the end, said one of three ways.
    if (k % 2 == 0) {
      const int form = std::uniform_int_distribution<int>(0, 2)(rng);
      said += form == 0 ? " minus a disc" : form == 1 ? " drilled with a disc" : " with a disc cut out";
      expected = "difference(" + expected + ", 'a disc')";
    }
    said = withFillers(rng, said);
    CsgQuery q;
    ASSERT_NO_THROW(q = parseCsgQuery(said, v(), {}, 1000)) << said;
    // Leaves keep the words as written: strip fillers from the expected texts' comparison by
    // comparing the tree shape with the leaf texts as the parser saw them.
    std::string got = testing::csgShape(q);
    for (const char* filler : {" please", " kindly"})
      for (size_t at; (at = got.find(filler)) != std::string::npos;) got.erase(at, std::string(filler).size());
    EXPECT_EQ(got, expected) << said;
  }
}

}  // namespace
}  // namespace fsdb
