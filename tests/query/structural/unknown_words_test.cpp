// readKnownWords (query/structural/unknown_words.h): the words of a search-box text that neither
// grammar knows, the text without them, and their corrections chosen together.
#include "query/structural/unknown_words.h"

#include <gtest/gtest.h>

#include <limits>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "query/linguistic/linguistic_query.h"
#include "query/structural/csg_query_text.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

TEST(UnknownWords, KnownTextsAreReadWhole) {
  for (const char* text : {"find a slightly bent cylinder", "a sphere on top of a cylinder",
                           "the union of a cube and a sphere about 2 units to its right", "a cube with a cylindrical hole",
                           "a sphere-shaped hole in a box", "bendness at least 0.5"}) {
    const KnownWordsReading r = readKnownWords(text, v());
    EXPECT_TRUE(r.unknown.empty()) << text << ": " << (r.unknown.empty() ? "" : r.unknown[0].word);
    EXPECT_EQ(r.text, text);
    EXPECT_FALSE(r.corrected) << text;
  }
}

// A hyphenated word whose head is known was read as known and then left out with its article
// ("a low-profile box" read "box"); now it routes as a compound. "-shaped" after a noun stays the
// CSG phrase's word.
TEST(UnknownWords, HyphenatedCompoundsRoute) {
  const KnownWordsReading r = readKnownWords("a low-profile box", v());
  EXPECT_TRUE(r.unknown.empty());
  EXPECT_EQ(r.text, "a low box");
  ASSERT_EQ(r.routed.size(), 1u);
  EXPECT_EQ(r.routed[0].route.why, "compound");
  EXPECT_EQ(readKnownWords("a cube with a sphere-shaped hole", v()).text, "a cube with a sphere-shaped hole");
  // A feature compound routes nowhere and is left out alone, its article kept.
  const KnownWordsReading edged = readKnownWords("a sharp-edged box", v());
  EXPECT_EQ(edged.text, "a box");
  ASSERT_EQ(edged.unknown.size(), 1u);
  EXPECT_EQ(edged.unknown[0].word, "sharp-edged");
}

// A noun the vocabulary lacks after an adjective stands as "thing" (and is still ignored), so the
// phrase keeps its head: "a hollow cylindrical" read as neither grammar.
TEST(UnknownWords, UnknownNounsAfterAnAdjectiveStandAsThing) {
  const KnownWordsReading r = readKnownWords("a hollow cylindrical housing", v());
  EXPECT_EQ(r.text, "a hollow cylindrical thing");
  ASSERT_EQ(r.unknown.size(), 1u);
  EXPECT_EQ(r.unknown[0].word, "housing");
  EXPECT_FALSE(r.corrected);
  // Not after an article alone, nor for a word WordNet lacks as a noun (a typo is corrected).
  EXPECT_EQ(readKnownWords("a housing on a cube", v()).text.find("thing"), std::string::npos);
  EXPECT_EQ(readKnownWords("a bent cylindr", v()).corrected.value_or(""), "a bent cylinder");
}

TEST(UnknownWords, FormulasKeepTheirNames) {
  const KnownWordsReading r = readKnownWords("snowman + \"very bent cylinder\"", v());
  EXPECT_TRUE(r.unknown.empty());
  EXPECT_EQ(r.text, "snowman + \"very bent cylinder\"");
}

TEST(UnknownWords, UnknownWordsGoWithTheirPositions) {
  const KnownWordsReading r = readKnownWords("find a slightly bnet Cylindr please", v());
  ASSERT_EQ(r.unknown.size(), 2u);
  EXPECT_EQ(r.unknown[0].word, "bnet");
  EXPECT_EQ(r.unknown[0].at, 16u);
  EXPECT_EQ(r.unknown[1].word, "cylindr");
  EXPECT_EQ(r.unknown[1].at, 21u);
  EXPECT_EQ(r.text, "find a slightly please");
  ASSERT_FALSE(r.unknown[0].closest.empty());
  EXPECT_EQ(r.unknown[0].closest[0], "bent");
  EXPECT_EQ(r.unknown[1].closest.at(0), "cylinder");
  // Chosen together: the text reads with both corrections.
  ASSERT_TRUE(r.corrected);
  EXPECT_EQ(*r.corrected, "find a slightly bent cylinder please");
  EXPECT_TRUE(isLinguisticQuery(*r.corrected, v()));
  // Each replaced word, where it is and what it became.
  ASSERT_EQ(r.corrections.size(), 2u);
  EXPECT_EQ(r.corrections[0].route.word, "bnet");
  EXPECT_EQ(r.corrections[0].route.became, "bent");
  EXPECT_EQ(r.corrections[0].route.why, "spelling");
  EXPECT_EQ(r.corrections[0].route.discount, kSpellingDiscount);
  EXPECT_EQ(r.corrections[0].at, 16u);
  EXPECT_EQ(r.corrections[1].route.became, "cylinder");
  EXPECT_EQ(r.corrections[1].at, 21u);
}

TEST(UnknownWords, JoiningWordsLeftWithNothingToJoinGoToo) {
  // (Words with no route: WordNet reads "dots" as small discs, word_routes.h.)
  EXPECT_EQ(readKnownWords("a round box with purple stripes", v()).text, "a round box");
  EXPECT_EQ(readKnownWords("a round box, with purple stripes, please", v()).text, "a round box, please");
  // Not when a known word follows.
  EXPECT_EQ(readKnownWords("a purple box", v()).text, "a box");
}

// A word order no grammar has: the longest run of words that reads, the first of the longest, with
// the words outside it listed; none where the text reads or the words left out make it read.
TEST(UnknownWords, TextsNoGrammarReadsAreReadByTheirLongestRun) {
  KnownWordsReading r = readKnownWords("a big box, height 2 x 3", v());
  ASSERT_TRUE(r.window.has_value());
  EXPECT_EQ(r.window->text, "a big box, height 2");
  std::string outside;
  for (const UnknownWord& u : r.window->outside) outside += u.word + "@" + std::to_string(u.at) + " ";
  EXPECT_EQ(outside, "x@20 3@22 ");
  // Unknown words are left out first, then the run is taken ("purple" is no word of the grammars);
  // the run with the most content words wins, the first of them ("cone" before "the box").
  r = readKnownWords("purple cone which stand on the box", v());
  ASSERT_TRUE(r.window.has_value());
  EXPECT_EQ(r.window->text, "cone");
  EXPECT_FALSE(r.unknown.empty());
  // Texts that read, or read without their unknown words, have no run.
  EXPECT_FALSE(readKnownWords("a big box", v()).window.has_value());
  EXPECT_FALSE(readKnownWords("a round box with purple stripes", v()).window.has_value());
  // Nothing reads: no run.
  EXPECT_FALSE(readKnownWords("purple elephant", v()).window.has_value());
}

TEST(UnknownWords, FarWordsHaveNoCorrection) {
  const KnownWordsReading r = readKnownWords("purple elephant", v());
  ASSERT_EQ(r.unknown.size(), 2u);
  EXPECT_TRUE(r.unknown[0].closest.empty()) << r.unknown[0].closest.at(0);
  EXPECT_TRUE(r.unknown[1].closest.empty()) << r.unknown[1].closest.at(0);
  EXPECT_EQ(r.text, "");
  EXPECT_FALSE(r.corrected);
}

// A word of the language is what the writer meant, not a typo: "pillow" is offered pillar but
// not read as it; "pilllar", which WordNet does not know, is.
TEST(UnknownWords, DictionaryWordsAreOfferedButNotCorrected) {
  const KnownWordsReading pillow = readKnownWords("a pillow", v());
  ASSERT_EQ(pillow.unknown.size(), 1u);
  ASSERT_FALSE(pillow.unknown[0].closest.empty());
  EXPECT_EQ(pillow.unknown[0].closest[0], "pillar");
  EXPECT_FALSE(pillow.corrected);
  EXPECT_TRUE(pillow.corrections.empty());
  const KnownWordsReading typo = readKnownWords("a pilllar", v());
  ASSERT_EQ(typo.unknown.size(), 1u);
  ASSERT_TRUE(typo.corrected);
  EXPECT_EQ(*typo.corrected, "a pillar");
}

TEST(UnknownWords, OnlyTheFirstSixteenAreCorrected) {
  std::string text = "a";
  for (int i = 0; i < 20; ++i) text += " bnet";
  text += " cylinder";
  const KnownWordsReading r = readKnownWords(text, v());
  ASSERT_EQ(r.unknown.size(), 20u);
  EXPECT_FALSE(r.unknown[15].closest.empty());
  EXPECT_TRUE(r.unknown[16].closest.empty());
  EXPECT_EQ(r.text, "a cylinder");
}

TEST(UnknownWords, CharactersNoQueryReadsAreTheTokenizersError) {
  EXPECT_THROW(readKnownWords("a cube ; drop table", v()), Error);
}

TEST(NearestNames, WithinTheDistanceNearestFirst) {
  // bnet: bent 1 (a swap), bet 1, sent 3
  const std::vector<std::string> known = {"bent", "bet", "sent", "cylinder"};
  EXPECT_EQ(nearestNames("bnet", known, 3, 2), (std::vector<std::string>{"bent", "bet"}));
  EXPECT_EQ(nearestNames("bnet", known, 1, 1), (std::vector<std::string>{"bent"}));
  EXPECT_EQ(nearestNames("bnet", known, 3, 3), (std::vector<std::string>{"bent", "bet", "sent"}));
  EXPECT_TRUE(nearestNames("pole", {"cone"}, 3, plausibleTypoDistance(4)).empty());
  EXPECT_TRUE(isAdjacentSwap("bnet", "bent"));
  EXPECT_TRUE(isAdjacentSwap("ab", "ba"));
  EXPECT_FALSE(isAdjacentSwap("bnet", "bnet"));
  EXPECT_FALSE(isAdjacentSwap("abc", "cba"));
  EXPECT_FALSE(isAdjacentSwap("abcd", "badc"));
  EXPECT_FALSE(isAdjacentSwap("ab", "abc"));
  EXPECT_TRUE(nearestNames("purple", known, 3, 2).empty());
  // A word far longer than any known one: no name within a third of it (distances past
  // kEditDistanceLimit are not told apart, so such a bound is that limit).
  EXPECT_TRUE(nearestNames(std::string(3000, 'q'), known, 3, 1000).empty());
  EXPECT_EQ(nearestNames(std::string(3000, 'q'), known, 2, std::numeric_limits<size_t>::max()).size(), 2u);
  EXPECT_EQ(plausibleTypoDistance(5), 1u);
  EXPECT_EQ(plausibleTypoDistance(6), 2u);
  EXPECT_EQ(plausibleTypoDistance(15), 3u);
}

TEST(QueryWords, BothGrammarsWords) {
  EXPECT_TRUE(knowsLinguisticWord("cylinder", v()));
  EXPECT_TRUE(knowsLinguisticWord("bendness", v()));
  EXPECT_TRUE(knowsLinguisticWord("that", v()));
  EXPECT_FALSE(knowsLinguisticWord("purple", v()));
  const auto& csg = csgPhraseWords();
  EXPECT_TRUE(std::is_sorted(csg.begin(), csg.end()));
  for (const char* w : {"union", "minus", "drilled", "united", "hollowed", "units"})
    EXPECT_TRUE(std::binary_search(csg.begin(), csg.end(), std::string(w))) << w;
  const auto correctable = correctableWords(v());
  EXPECT_NE(std::find(correctable.begin(), correctable.end(), "cylinder"), correctable.end());
  EXPECT_EQ(std::find(correctable.begin(), correctable.end(), "are"), correctable.end());
}

}  // namespace
}  // namespace fsdb
