// Parts from words: the noun's parameters, adjectives through the inverse descriptor functions,
// so the descriptors of the part made from "a very bent cylinder" are what the words say.
#include "query/document/part_from_words.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }
FuzzyPart make(const std::string& text) { return partFromWords(text, v()); }
FuzzyNumber valueOf(const FuzzyPart& p, const std::string& descriptor) {
  return describePart(p)[descriptorIndex(descriptor)].value;
}

std::string errorOf(const std::string& text) {
  try {
    make(text);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kInvalidParameter);
    EXPECT_EQ(e.path(), "text");
    return e.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return "";
}

TEST(PartFromWords, NounGivesTheParameters) {
  const FuzzyPart cube = make("a cube");
  EXPECT_EQ(cube.eps1, FuzzyNumber::crisp(0.1));
  EXPECT_EQ(cube.eps2, FuzzyNumber::crisp(0.1));
  EXPECT_EQ(cube.a1, FuzzyNumber::crisp(1));
  EXPECT_EQ(make("double pyramid").eps1, FuzzyNumber::crisp(2));
  EXPECT_EQ(make("the ball").eps1, FuzzyNumber::crisp(1));
}

// The descriptor of the made part equals the words' degree set (exact for the affine rules).
TEST(PartFromWords, AdjectivesSetTheirDescriptor) {
  const FuzzyPart bent = make("a slightly bent cylinder");
  const FuzzyNumber bend = valueOf(bent, "bendness");
  for (double alpha : {0.0, 0.5, 1.0}) {
    EXPECT_NEAR(bend.alphaCut(alpha).lo, v().intensity("slightly")->alphaCut(alpha).lo, 1e-9);
    EXPECT_NEAR(bend.alphaCut(alpha).hi, v().intensity("slightly")->alphaCut(alpha).hi, 1e-9);
  }
  EXPECT_NEAR(similarity(valueOf(make("a very twisted box"), "twistness"), *v().intensity("very")), 1.0, 1e-9);
  EXPECT_NEAR(similarity(valueOf(make("an extremely tapered rod"), "taperness"), *v().intensity("extremely")), 1.0, 1e-9);
  EXPECT_NEAR(similarity(valueOf(make("a very bevelled cube"), "bevelness"), *v().intensity("very")), 1.0, 1e-9);
  // Plain adjectives take the vocabulary's create set, or their own.
  EXPECT_NEAR(similarity(valueOf(make("a bent rod"), "bendness"), v().plainCreate()), 1.0, 1e-9);
  EXPECT_EQ(make("a straight rod").kv, FuzzyNumber::crisp(0));
  // Proportions and size: long, flat, small and large move elongation and size the right way.
  const double sphereSize = valueOf(make("a sphere"), "size").core().lo;
  EXPECT_GT(valueOf(make("a large sphere"), "size").core().lo, sphereSize);
  EXPECT_LT(valueOf(make("a small sphere"), "size").core().hi, sphereSize);
  EXPECT_GT(valueOf(make("a long box"), "elongation").core().lo, 0.7);
  EXPECT_LT(valueOf(make("a flat box"), "elongation").core().hi, 0.15);
  EXPECT_NEAR(valueOf(make("a very flat box"), "elongation").core().hi, 0.25, 1e-9);  // 1 − the core start of very
}

// A part made from words is found by the same words.
TEST(PartFromWords, FoundByItsOwnWords) {
  for (const char* words : {"a slightly bent cylinder", "a very bent cylinder", "a very twisted box",
                            "an extremely tapered cone", "a long, slightly twisted rod", "a very round sphere",
                            "a flat disc", "a moderately bent and very twisted plate"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_GT(scoreDescriptors(q, describePart(make(words))).score, 0.15) << words;
  }
  // And ranks above the other words' parts.
  const LinguisticQuery very = parseLinguisticQuery("find a very bent cylinder", v());
  EXPECT_GT(scoreDescriptors(very, describePart(make("a very bent cylinder"))).score,
            scoreDescriptors(very, describePart(make("a slightly bent cylinder"))).score);
}

TEST(PartFromWords, AdjectivesActInATableOrder) {
  // The bend is measured on the final length: "bent long" equals "long bent".
  const FuzzyPart a = make("a slightly bent long rod"), b = make("a long slightly bent rod");
  EXPECT_EQ(a.kv, b.kv);
  EXPECT_EQ(a.a3, b.a3);
}

TEST(PartFromWords, Errors) {
  EXPECT_NE(errorOf("a slightly bnet cylinder").find("closest known words: bent"), std::string::npos);
  EXPECT_NE(errorOf("a slightly bnet cylinder").find("did you mean \"a slightly bent cylinder\"?"), std::string::npos);
  EXPECT_NE(errorOf("a bent shape").find("names no shape"), std::string::npos);
  EXPECT_NE(errorOf("a very cylinder").find("expected an adjective"), std::string::npos);
  EXPECT_NE(errorOf("a bent cylinder above a cube").find("end of the description"), std::string::npos);
  EXPECT_NE(errorOf("slightly bent").find("a noun"), std::string::npos);
  EXPECT_NE(errorOf("").find("words such as"), std::string::npos);
}

}  // namespace
}  // namespace fsdb
