// The tokens of query texts (query/linguistic/query_tokens.h): words, numbers and punctuation with
// their offsets; fillers dropped with the comma that sets them off; phrases and requests matched
// word by word.
#include "query/linguistic/query_tokens.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"

namespace fsdb::query_tokens {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }

std::string texts(const std::vector<Token>& tokens) {
  std::string out;
  for (const Token& t : tokens) out += (out.empty() ? "" : "|") + t.text;
  return out;
}

std::vector<Token> tokens(const std::string& text) { return tokenize(text, 0, text.size()); }

// wordAt over the tokens from `pos` on.
auto wordsFrom(const std::vector<Token>& t, size_t pos) {
  return [&t, pos](size_t k) { return pos + k < t.size() ? &t[pos + k].text : nullptr; };
}

TEST(QueryTokens, WordsNumbersAndPunctuationWithOffsets) {
  const std::vector<Token> t = tokens("Find (bent, 0.5) I'm");
  EXPECT_EQ(texts(t), "find|(|bent|,|0.5|)|i'm");
  EXPECT_EQ(t[2].offset, 6u);
  EXPECT_EQ(t[2].end, 10u);
  EXPECT_TRUE(t[4].number);
  EXPECT_THROW(tokens("bent #"), Error);
}

TEST(QueryTokens, ShorthandsOfNotesAreWords) {
  const std::vector<Token> t = tokens("plate w/ peg, ball ~3 across w hole");
  EXPECT_EQ(texts(t), "plate|with|peg|,|ball|about|3|across|with|hole");
  EXPECT_EQ(t[1].offset, 6u);
  EXPECT_EQ(t[1].end, 8u);
  EXPECT_EQ(t[5].offset, 19u);
  EXPECT_EQ(t[5].end, 20u);
  EXPECT_EQ(texts(tokens("wide wheels")), "wide|wheels");  // only the lone letter
  EXPECT_THROW(tokens("plate / peg"), Error);
}

TEST(QueryTokens, FillersGoWithTheCommaThatSetsThemOff) {
  EXPECT_EQ(texts(withoutFillers(tokens("please, find round, please, tapered shapes, please"), v())),
            "find|round|,|tapered|shapes");
  EXPECT_EQ(texts(withoutFillers(tokens("a cube, please a sphere"), v())), "a|cube|,|a|sphere");
  EXPECT_EQ(texts(withoutFillers(tokens("kindly show bent"), v())), "show|bent");
}

// A repeated intensity steps up the order, one term per repetition, as far as the strongest; the
// words keep the first one's place; different intensities in a row stay as they are.
TEST(QueryTokens, ReadableWordsStepRepeatedIntensitiesUp) {
  EXPECT_EQ(texts(readableWords(tokens("a very very long box"), v())), "a|extremely|long|box");
  EXPECT_EQ(texts(readableWords(tokens("really really big, please"), v())), "extremely|big");
  EXPECT_EQ(texts(readableWords(tokens("slightly slightly slightly bent"), v())), "moderately|bent");
  EXPECT_EQ(texts(readableWords(tokens("a very, very long box"), v())), "a|extremely|long|box");
  EXPECT_EQ(texts(readableWords(tokens("extremely extremely bent"), v())), "extremely|bent");
  EXPECT_EQ(texts(readableWords(tokens("very slightly bent"), v())), "very|slightly|bent");
  const std::vector<Token> t = readableWords(tokens("a very very long box"), v());
  EXPECT_EQ(t[1].offset, 2u);
}

// "as ADJECTIVE as ..." keeps the adjective, plain, and drops what it is compared with, up to a
// comma or a joining word, four words at most; not where the word between is no adjective.
TEST(QueryTokens, ComparisonsKeepTheirAdjective) {
  EXPECT_EQ(texts(readableWords(tokens("a ball as big as a house"), v())), "a|ball|big");
  EXPECT_EQ(texts(readableWords(tokens("a rod as thin as a pencil, slightly bent"), v())), "a|rod|thin|,|slightly|bent");
  EXPECT_EQ(texts(readableWords(tokens("a cube as small as a die and rounded"), v())), "a|cube|small|and|rounded");
  EXPECT_EQ(texts(readableWords(tokens("as long as one two three four five"), v())), "long|five");
  EXPECT_EQ(texts(readableWords(tokens("a cube as well as a ball"), v())), "a|cube|as|well|as|a|ball");
  const std::vector<Token> t = readableWords(tokens("a ball as big as a house"), v());
  EXPECT_EQ(t[2].offset, 10u);  // the adjective's own place
  const auto at = [](const std::vector<std::string>& w) {
    return [&w](size_t k) { return k < w.size() ? &w[k] : nullptr; };
  };
  const std::vector<std::string> a = {"as", "big", "as", "a", "house"}, b = {"as", "big"}, c = {"as", "big", "as"};
  EXPECT_EQ(comparisonLength(at(a)), 5u);
  EXPECT_EQ(comparisonLength(at(b)), 0u);
  EXPECT_EQ(comparisonLength(at(c)), 3u);
}

TEST(QueryTokens, DegreeWordsSayAnIntensityOfTheVocabulary) {
  ASSERT_FALSE(degreeWords().empty());
  for (const auto& [word, term] : degreeWords()) EXPECT_NE(v().intensity(term), nullptr) << word << " -> " << term;
}

TEST(QueryTokens, FunctionWordsCarryNoPropertyOfAShape) {
  for (const char* w : {"a", "the", "and", "with", "of", "its", "has", "for"}) EXPECT_TRUE(functionWord(w)) << w;
  for (const char* w : {"bent", "cylinder", "not", "without", "box", ",", ""}) EXPECT_FALSE(functionWord(w)) << w;
}

TEST(QueryTokens, PhrasesAndRequests) {
  const std::vector<Token> t = tokens("i am looking for a double pyramid");
  EXPECT_EQ(phraseLength(wordsFrom(t, 5), "double pyramid"), 2u);
  EXPECT_EQ(phraseLength(wordsFrom(t, 5), "double cone"), 0u);
  EXPECT_EQ(phraseLength(wordsFrom(t, 6), "pyramid base"), 0u);  // runs past the end
  EXPECT_EQ(requestLength(wordsFrom(t, 0), v()), 4u);
  const std::vector<Token> verb = tokens("search for bent shapes");
  EXPECT_EQ(requestLength(wordsFrom(verb, 0), v()), 2u);  // a verb with its "for"
  const std::vector<Token> longest = tokens("show me bent shapes");
  EXPECT_EQ(requestLength(wordsFrom(longest, 0), v()), 2u);  // "show me" before "show"
  const std::vector<Token> none = tokens("bent shapes");
  EXPECT_EQ(requestLength(wordsFrom(none, 0), v()), 0u);
}

}  // namespace
}  // namespace fsdb::query_tokens
