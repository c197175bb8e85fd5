// Word routes (query/linguistic/word_routes.h) onto the built-in vocabulary through Debian's
// WordNet: each kind of route with its discount, the rare senses that route nowhere, and words
// with no route.
#include "query/linguistic/word_routes.h"

#include <gtest/gtest.h>

#include "query/linguistic/linguistic_query.h"

namespace fsdb {
namespace {

std::optional<WordRoute> route(const std::string& word, const std::string& next = "") {
  const WordNet* wn = systemWordNet();
  EXPECT_NE(wn, nullptr) << "no WordNet in " << wordNetDirectory();
  const Vocabulary& v = Vocabulary::builtin();
  // The grammars' words as the search box knows them, plus the joining and cutting words of the
  // CSG phrase form.
  const auto known = [&](const std::string& w) { return knowsLinguisticWord(w, v) || w == "joined" || w == "drilled"; };
  return routeWord(word, next, v, wn, known);
}

void expectRoute(const std::string& word, const std::string& became, const std::string& why, double discount,
                 const std::string& next = "") {
  const std::optional<WordRoute> r = route(word, next);
  ASSERT_TRUE(r.has_value()) << word;
  EXPECT_EQ(r->word, word);
  EXPECT_EQ(r->became, became) << word << " via " << r->via;
  EXPECT_EQ(r->why, why) << word << " via " << r->via;
  EXPECT_DOUBLE_EQ(r->discount, discount) << word;
}

TEST(WordRoutes, InflectionsOfKnownWordsAreTheirLemmas) {
  expectRoute("rounder", "round", "lemma", 1.0);
  expectRoute("biggest", "big", "lemma", 1.0);
  expectRoute("straighter", "straight", "lemma", 1.0);
}

TEST(WordRoutes, VerbsOfAssemblyAreReadByTheirLemmas) {
  expectRoute("glued", "joined", "joining verb", 1.0);
  expectRoute("welded", "joined", "joining verb", 1.0);
  expectRoute("bored", "drilled", "cutting verb", 1.0);
  expectRoute("punched", "drilled", "cutting verb", 1.0);
  // A verb of resting is left out before a relation word, and only there.
  expectRoute("resting", "", "support verb", 1.0, "on");
  expectRoute("lying", "", "support verb", 1.0, "under");
  expectRoute("sits", "", "support verb", 1.0, "atop");
  EXPECT_FALSE(route("resting", "cylinder").has_value());
}

TEST(WordRoutes, WordNetLinksReachTheVocabularyWithTheirDiscounts) {
  expectRoute("little", "small", "WordNet synonym", 0.95);        // the synset {small, little}
  expectRoute("colossal", "large", "WordNet similar-to", 0.9);    // a satellite of large
  expectRoute("huge", "large", "WordNet similar-to", 0.9);
  expectRoute("curvy", "curved", "WordNet similar-to", 0.9);
  expectRoute("skinny", "thin", "WordNet similar-to", 0.9);
  expectRoute("lean", "thin", "WordNet synonym", 0.95);        // the synset {lean, thin}
  expectRoute("crooked", "bent", "WordNet antonym", 0.85);        // the other pole of straight
  expectRoute("curvier", "curved", "WordNet similar-to", 0.9);    // its lemma curvy, then WordNet
}

TEST(WordRoutes, AdjectivesByYAndIshReachTheirStemsAdjective) {
  expectRoute("twisty", "twisted", "derivation", 0.9);  // WordNet: similar to crooked, antonym 0.765
  expectRoute("pointy", "pointed", "derivation", 0.9);  // not in WordNet
  expectRoute("bendy", "bent", "derivation", 0.9);      // bent's verb by the exception list
  expectRoute("sharpish", "sharp", "derivation", 0.9);
  expectRoute("thinnish", "thin", "derivation", 0.9);   // the doubled letter undone
  expectRoute("flattish", "flat", "derivation", 0.9);
  // Verbs made from an adjective by -en, in any form: the adjective ("flattened" -> flatten -> flat).
  expectRoute("flattened", "flat", "derivation", 0.9);  // the doubled letter undone
  expectRoute("widened", "wide", "derivation", 0.9);
  expectRoute("straightened", "straight", "derivation", 0.9);
  expectRoute("broadens", "broad", "derivation", 0.9);
  // WordNet's own links still win: "thickening" is a noun, a synonym of knob.
  expectRoute("thickening", "knob", "WordNet synonym", 0.95);
  expectRoute("biggish", "large", "WordNet similar-to", 0.9);  // WordNet's own link first
  expectRoute("curvy", "curved", "WordNet similar-to", 0.9);  // WordNet wins the tie
  // Only adjectives are targets: "party" is not a part, "penny" no pen.
  for (const char* w : {"party", "penny", "jelly", "bumpy"}) {
    const std::optional<WordRoute> r = route(w);
    if (r) {
      EXPECT_NE(r->why, "derivation") << w << " -> " << r->became;
    }
  }
}

// An adverb made from a grading adjective reads as that adjective's intensity: WordNet's
// pertainym link, then the grading word itself, a synonym of it or its satellite's head.
TEST(WordRoutes, AdverbsOfDegreeReadAsTheirAdjectivesIntensity) {
  expectRoute("gently", "slightly", "WordNet pertainym", 0.9);   // gently -> gentle
  expectRoute("mildly", "slightly", "WordNet pertainym", 0.9);   // mildly -> mild
  expectRoute("heavily", "very", "WordNet pertainym", 0.9);      // heavily -> heavy
  expectRoute("sharply", "very", "WordNet pertainym", 0.9);      // its third sense, -> sharp
  expectRoute("greatly", "very", "WordNet pertainym", 0.9 * 0.9);  // great -> large
  expectRoute("severely", "very", "WordNet pertainym", 0.9 * 0.9);  // severe -> strong
  // An adverb of no grading adjective routes nowhere by this link ("perfectly" -> perfect).
  EXPECT_FALSE(route("perfectly").has_value());
  // A known intensity is no route at all; the lemma route never reaches a function word.
  EXPECT_FALSE(route("as").has_value());
}

TEST(WordRoutes, NounsReachTheirMoreGeneralNoun) {
  expectRoute("wand", "rod", "WordNet hypernym", 0.9);
  expectRoute("ingot", "block", "WordNet hypernym", 0.9);
  expectRoute("marble", "ball", "WordNet hypernym", 0.9);         // its second sense: a small ball
  expectRoute("wands", "rods", "WordNet hypernym", 0.9);          // a plural stays plural
}

TEST(WordRoutes, ParticiplesOfVerbsReachTheirSynonymsParticiple) {
  expectRoute("flexed", "bent", "WordNet synonym", 0.95);      // flex = bend
  expectRoute("crushed", "squashed", "WordNet synonym", 0.95); // crush = squash
  // WordNet's links from an adjective come first: "arched" is an adjective, a synonym of bowed.
  expectRoute("arched", "bowed", "WordNet synonym", 0.95);
  // A later sense of the verb where it is the synonym's first: stretch's fifth is elongate's first.
  expectRoute("stretched", "elongated", "WordNet synonym", 0.95);
  // Not where it is a later sense of the synonym too: point's first sense (indicate) is show's
  // seventh, and "shown" says nothing of a pointed part (it is the grammar's "show").
  const std::optional<WordRoute> shown = route("shown");
  ASSERT_TRUE(shown.has_value());
  EXPECT_EQ(shown->became, "show");
  // A verb's other forms say what a part does: spin = twist, but "spinning" and "flexes" are no
  // twisted or bent part.
  for (const char* w : {"spinning", "flexes"}) {
    const std::optional<WordRoute> r = route(w);
    if (r) {
      EXPECT_EQ(r->via.find(" = "), std::string::npos) << w << " -> " << r->became << " via " << r->via;
    }
  }
}

// Hyphenated compounds WordNet lacks read as their adjective part: the last ("paper-thin"), else
// for "-like" and "-shaped" after a noun whose shape an adjective names that adjective, else the
// first ("low-profile"); an adjective with a participle of a noun ("sharp-edged") routes nowhere. A compound WordNet has keeps its
// links ("wafer-thin" is similar to thin there).
TEST(WordRoutes, HyphenatedCompoundsReadAsTheirAdjectivePart) {
  expectRoute("low-profile", "low", "compound", 0.9);
  expectRoute("paper-thin", "thin", "compound", 0.9);
  expectRoute("extra-long", "long", "compound", 0.9);
  expectRoute("cylinder-like", "cylindrical", "compound", 0.9);
  // An adjective with a noun made a participle says a feature: a sharp-edged box is no pointed box.
  for (const char* feature : {"sharp-edged", "flat-topped", "thin-walled", "round-ended", "skinny-legged"})
    EXPECT_FALSE(route(feature).has_value()) << feature;
  expectRoute("wafer-thin", "thin", "WordNet similar-to", 0.9);
  EXPECT_FALSE(route("purple-spotted").has_value());
  EXPECT_FALSE(route("kettle-shaped").has_value());
}

// A noun by -ish, -y or -like reads as the adjective that names its shape, unless WordNet has the
// word as an adjective of its own.
TEST(WordRoutes, NounsByIshYAndLikeReachTheirShapesAdjective) {
  expectRoute("conish", "conical", "derivation", 0.9);
  expectRoute("tubey", "tubular", "derivation", 0.9);
  expectRoute("ballish", "spherical", "derivation", 0.9);
  const std::optional<WordRoute> bally = route("bally");  // a British oath in WordNet
  EXPECT_TRUE(!bally || bally->became != "spherical");
  const std::optional<WordRoute> conelike = route("conelike");
  ASSERT_TRUE(conelike.has_value());
  EXPECT_EQ(conelike->became, "conical");
}

// An adjective of the vocabulary marked written_only is no route's target: "low" is a profile, but
// WordNet's "blue", "gloomy" and "crushed" are low in spirits. And a word WordNet has as an
// adjective is not read as a verb's lemma: "towering" is no form of the noun "tower".
TEST(WordRoutes, WrittenOnlyAdjectivesAndAdjectivesThemselves) {
  EXPECT_FALSE(route("blue").has_value());
  EXPECT_FALSE(route("gloomy").has_value());
  expectRoute("crushed", "squashed", "WordNet synonym", 0.95);
  const std::optional<WordRoute> towering = route("towering");
  EXPECT_TRUE(!towering || towering->became != "tower");
}

TEST(WordRoutes, AbbreviationsOfOneWordReachIt) {
  expectRoute("cyl", "cylinder", "abbreviation", 0.9);
  expectRoute("cyls", "cylinders", "abbreviation", 0.9);  // a plural stays plural
  expectRoute("pyr", "pyramid", "abbreviation", 0.9);
  expectRoute("colu", "column", "abbreviation", 0.9);  // not "columns": the shortest spelling
  // Two nouns of other meanings (sphere, spheroid): the one adjective, spherical.
  expectRoute("sph", "spherical", "abbreviation", 0.9);
  expectRoute("rect", "rectangular", "abbreviation", 0.9); // no noun begins so: the adjective
  // Too short, two nouns begin so, or a word WordNet has: no abbreviation.
  EXPECT_FALSE(route("cy").has_value());
  EXPECT_FALSE(route("co").has_value());                  // cone, coin, column, ...
  EXPECT_FALSE(route("cylindr").has_value());             // cylinder misspelt: for the corrections
  EXPECT_FALSE(route("pil").has_value());                 // pin, one letter away
  for (const char* w : {"cub", "pill"}) {                 // WordNet nouns (cube, pillar begin so)
    const std::optional<WordRoute> r = route(w);
    if (r) {
      EXPECT_NE(r->why, "abbreviation") << w << " -> " << r->became;
    }
  }
}

TEST(WordRoutes, RareSensesUnknownWordsAndNonWordsRouteNowhere) {
  EXPECT_FALSE(route("purple").has_value());   // a colour: no shape word near it
  EXPECT_FALSE(route("sphre").has_value());    // a typo is for the corrections, not WordNet
  EXPECT_FALSE(route("egg").has_value());      // "ball" only in a sense of the body
  EXPECT_FALSE(route("3d").has_value());
  EXPECT_FALSE(routeWord("colossal", "", Vocabulary::builtin(), nullptr, [](const std::string&) { return true; }));
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

const auto knownLinguistic = [](const std::string& w) { return knowsLinguisticWord(w, Vocabulary::builtin()); };

// The routes of the marked tokens only, each read with the word after it.
TEST(WordRoutes, RouteTokensRoutesTheMarkedTokensWithTheirNextWords) {
  const std::string text = "a skinny ball sitting on a chunky box";
  const auto tokens = query_tokens::tokenize(text, 0, text.size());
  const auto routes = routeTokens(
      tokens, [&](size_t i) { return tokens[i].text != "chunky" && !knownLinguistic(tokens[i].text); },
      Vocabulary::builtin(), systemWordNet(), knownLinguistic);
  ASSERT_EQ(routes.size(), 2u);
  EXPECT_EQ(tokens[routes[0].token].text, "skinny");
  EXPECT_EQ(routes[0].route.became, "thin");
  EXPECT_EQ(tokens[routes[1].token].text, "sitting");
  EXPECT_EQ(routes[1].route.why, "support verb");  // "on" follows it
  EXPECT_TRUE(routeTokens(tokens, [](size_t) { return true; }, Vocabulary::builtin(), nullptr, knownLinguistic).empty());
}

// Right after "that" or "which", a form of a verb whose participle is a known adjective says what
// the part is: "a rod that tapers" is a rod that is tapered. Elsewhere, and for verbs without
// such a participle ("spins"), no such route.
TEST(WordRoutes, AShapeVerbAfterThatSaysWhatThePartIs) {
  const Vocabulary& v = Vocabulary::builtin();
  const WordNet* wn = systemWordNet();
  ASSERT_NE(wn, nullptr);
  const auto stative = routeStativeVerb("tapers", v, *wn);
  ASSERT_TRUE(stative.has_value());
  EXPECT_EQ(stative->became, "is tapered");
  EXPECT_EQ(stative->why, "stative verb");
  EXPECT_EQ(stative->via, "tapers -> taper -> tapered");
  EXPECT_DOUBLE_EQ(stative->discount, 1.0);
  EXPECT_EQ(routeStativeVerb("twist", v, *wn)->became, "is twisted");
  EXPECT_EQ(routeStativeVerb("bends", v, *wn)->became, "is bent");
  EXPECT_FALSE(routeStativeVerb("spins", v, *wn).has_value());
  const auto routed = routeUnknownWords("rods which taper and a box that twists", v, wn, knownLinguistic);
  ASSERT_TRUE(routed.has_value());
  EXPECT_EQ(routed->text, "rods which is tapered and a box that is twisted");
  // Not after another word: "tapers" there is no stative verb.
  const auto elsewhere = routeUnknownWords("a rod tapers", v, wn, knownLinguistic);
  EXPECT_TRUE(!elsewhere || elsewhere->routes.empty() || elsewhere->routes[0].why != "stative verb");
}

// The text with each routed word replaced, a left-out word with the blank before it.
TEST(WordRoutes, RouteUnknownWordsRewritesTheText) {
  const auto routed = routeUnknownWords("a skinny ball sitting on a box", Vocabulary::builtin(), systemWordNet(),
                                        knownLinguistic);
  ASSERT_TRUE(routed.has_value());
  EXPECT_EQ(routed->text, "a thin ball on a box");
  ASSERT_EQ(routed->routes.size(), 2u);
  EXPECT_EQ(routed->routes[0].word, "skinny");
  EXPECT_FALSE(routeUnknownWords("a thin ball", Vocabulary::builtin(), systemWordNet(), knownLinguistic).has_value());
}

}  // namespace
}  // namespace fsdb
