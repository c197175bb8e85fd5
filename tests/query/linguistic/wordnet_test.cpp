// WordNet (query/linguistic/wordnet.h) over Debian's wordnet-base (scripts/install-deps installs
// it): base forms by the exception lists and the detachment rules, senses in frequency order with
// their pointers, and a directory without WordNet.
#include "query/linguistic/wordnet.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace fsdb {
namespace {

using Pos = WordNet::Pos;

bool has(const std::vector<std::string>& list, const std::string& w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}

const WordNet& wordnet() {
  const WordNet* wn = systemWordNet();
  if (!wn) {
    ADD_FAILURE() << "no WordNet in " << wordNetDirectory() << " (scripts/install-deps installs wordnet-base)";
    std::abort();
  }
  return *wn;
}

TEST(WordNet, BaseFormsFollowTheExceptionListsAndTheDetachmentRules) {
  const WordNet& wn = wordnet();
  EXPECT_TRUE(has(wn.baseForms("balls", Pos::kNoun), "ball"));
  EXPECT_TRUE(has(wn.baseForms("boxes", Pos::kNoun), "box"));
  EXPECT_TRUE(has(wn.baseForms("resting", Pos::kVerb), "rest"));
  EXPECT_TRUE(has(wn.baseForms("lying", Pos::kVerb), "lie"));        // verb.exc
  EXPECT_TRUE(has(wn.baseForms("thinner", Pos::kAdjective), "thin"));  // adj.exc
  EXPECT_TRUE(has(wn.baseForms("bigger", Pos::kAdjective), "big"));
  EXPECT_EQ(wn.baseForms("cylinder", Pos::kNoun).front(), "cylinder");  // a lemma is its own base
  EXPECT_TRUE(wn.baseForms("qqqq", Pos::kNoun).empty());
  EXPECT_TRUE(wn.baseForms("cylinder", Pos::kAdverb).empty());
}

TEST(WordNet, SensesComeInFrequencyOrderWithTheirPointers) {
  const WordNet& wn = wordnet();
  const std::vector<WordNet::Synset> pole = wn.senses("pole", Pos::kNoun);
  ASSERT_GE(pole.size(), 10u);
  // The first sense of "pole" is "a long (usually round) rod of wood or metal or plastic": its
  // hypernym is rod.
  bool rod = false;
  for (const WordNet::Pointer& p : pole[0].pointers)
    if (p.symbol == "@") rod = rod || has(wn.synsetAt(p.pos, p.offset).words, "rod");
  EXPECT_TRUE(rod);
  // "colossal" is a satellite of large/big.
  const std::vector<WordNet::Synset> colossal = wn.senses("colossal", Pos::kAdjective);
  ASSERT_FALSE(colossal.empty());
  EXPECT_TRUE(colossal[0].satellite);
  bool large = false;
  for (const WordNet::Pointer& p : colossal[0].pointers)
    if (p.symbol == "&") large = large || has(wn.synsetAt(p.pos, p.offset).words, "large");
  EXPECT_TRUE(large);
  // Multi-word lemmas read with blanks.
  EXPECT_FALSE(wn.senses("hockey puck", Pos::kNoun).empty());
  EXPECT_TRUE(has(wn.senses("hockey puck", Pos::kNoun)[0].words, "hockey puck"));
  EXPECT_TRUE(wn.senses("qqqq", Pos::kNoun).empty());
}

TEST(WordNet, ADirectionWithoutWordNetOpensNothingAndSaysWhy) {
  std::string why;
  EXPECT_EQ(WordNet::open(std::filesystem::temp_directory_path().string() + "/no-wordnet-here", &why), nullptr);
  EXPECT_NE(why.find("index.noun"), std::string::npos) << why;
}

}  // namespace
}  // namespace fsdb
