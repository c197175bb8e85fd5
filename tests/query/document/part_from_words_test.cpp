// Parts from words: the noun's parameters, adjectives through the inverse descriptor functions,
// so the descriptors of the part made from "a very bent cylinder" are what the words say.
#include "query/document/part_from_words.h"

#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "geometry/superquadric/deformation.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/part_json.h"
#include "query/json/fuzzy_json.h"
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
// An adjective that names a noun's shape, on a noun with no shape of its own, makes that noun.
TEST(PartFromWords, AnAdjectiveThatNamesAShapeMakesItsNoun) {
  const auto same = [](const std::string& a, const std::string& b) { return partToJson(make(a)) == partToJson(make(b)); };
  EXPECT_TRUE(same("a cylindrical thing", "a cylinder"));
  EXPECT_TRUE(same("a slightly bent conical part", "a slightly bent cone"));
  EXPECT_TRUE(same("a small spherical object", "a small sphere"));
  EXPECT_FALSE(same("a cylindrical box", "a cylinder"));  // a box with a round section
  EXPECT_NE(errorOf("a very cylindrical thing").find("names no shape"), std::string::npos);
}

// A deformation said as a noun after "with" makes the part its adjective makes.
TEST(PartFromWords, AFeatureNounIsItsAdjective) {
  const auto same = [](const std::string& a, const std::string& b) { return partToJson(make(a)) == partToJson(make(b)); };
  EXPECT_TRUE(same("a cylinder with a slight bend", "a slightly bent cylinder"));
  EXPECT_TRUE(same("a box with a twist", "a twisted box"));
  EXPECT_TRUE(same("a rod with a strong taper", "a very tapered rod"));
  EXPECT_TRUE(same("a rod with an extreme curve", "an extremely curved rod"));
  EXPECT_TRUE(same("a cone with its top cut off", "a truncated cone"));
}

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
  // Plain adjectives take one degree, the middle of the core of the vocabulary's create set (or
  // their own), which their plain set holds fully.
  const FuzzyNumber bendOfBent = valueOf(make("a bent rod"), "bendness");
  EXPECT_NEAR(bendOfBent.core().lo, 0.5 * (v().plainCreate().core().lo + v().plainCreate().core().hi), 1e-9);
  EXPECT_NEAR(bendOfBent.support().hi - bendOfBent.support().lo, 0.0, 1e-9);
  EXPECT_NEAR(similarity(bendOfBent, v().plainSet(*v().adjective("bent"))), 1.0, 1e-9);
  EXPECT_EQ(make("a straight rod").kv, FuzzyNumber::crisp(0));
  // Proportions and size: long and flat set slenderness and flatness to one degree in their
  // create sets' cores, or to their intensities (and move elongation the right way); small and
  // large move size.
  const double sphereSize = valueOf(make("a sphere"), "size").core().lo;
  EXPECT_GT(valueOf(make("a large sphere"), "size").core().lo, sphereSize);
  EXPECT_LT(valueOf(make("a small sphere"), "size").core().hi, sphereSize);
  const FuzzyNumber longSet = v().createdSet(*v().adjective("long"), nullptr),
                    flatSet = v().createdSet(*v().adjective("flat"), nullptr);
  EXPECT_TRUE(longSet.isCrisp());
  EXPECT_NEAR(longSet.core().lo, 0.65, 1e-12);  // the middle of long's create core [0.6, 0.7]
  // The degree is the created one at its core and support (exact at the breakpoints; between
  // them the ratio of linearly interpolated axes is not linear in alpha).
  const auto expectSet = [](const FuzzyNumber& value, const FuzzyNumber& set, const char* words) {
    for (double alpha : {0.0, 1.0}) {
      EXPECT_NEAR(value.alphaCut(alpha).lo, set.alphaCut(alpha).lo, 1e-9) << words << " alpha " << alpha;
      EXPECT_NEAR(value.alphaCut(alpha).hi, set.alphaCut(alpha).hi, 1e-9) << words << " alpha " << alpha;
    }
  };
  expectSet(valueOf(make("a long box"), "slenderness"), longSet, "a long box");
  expectSet(valueOf(make("a flat box"), "flatness"), flatSet, "a flat box");
  const double boxElongation = valueOf(make("a box"), "elongation").core().lo;  // 0.5: a cube
  EXPECT_GT(valueOf(make("a long box"), "elongation").core().lo, boxElongation + 0.1);
  EXPECT_LT(valueOf(make("a flat box"), "elongation").core().hi, boxElongation - 0.2);
  EXPECT_NEAR(valueOf(make("a very flat box"), "flatness").core().lo, 0.75, 1e-9);  // the core start of very
  EXPECT_NEAR(valueOf(make("a very flat box"), "flatness").core().hi, 0.99, 1e-9);  // very's 1, cut at 0.99
  // Both on one part, whichever axis the noun has longest: each is its own set.
  for (const char* words : {"a long flat box", "a flat long box", "a long flat disc"}) {
    const FuzzyPart part = make(words);
    expectSet(valueOf(part, "slenderness"), longSet, words);
    expectSet(valueOf(part, "flatness"), flatSet, words);
  }
  // A board keeps its own long and flat conditions: the words take a degree inside both (the
  // created degrees 0.65 are short of a board's slenderness and flatness cores).
  const FuzzyPart board = make("a long flat board");
  const LinguisticQuery asked = parseLinguisticQuery("find a long flat board", v());
  EXPECT_EQ(scoreDescriptors(asked, describePart(board)).score, 1.0);
  EXPECT_GT(valueOf(board, "slenderness").core().lo, longSet.core().hi);
  EXPECT_GT(valueOf(board, "flatness").core().lo, flatSet.core().hi);
  // A board is long and flat without the words; "a flat board" keeps its length.
  EXPECT_GT(valueOf(make("a board"), "slenderness").core().lo, 0.6);
  EXPECT_GT(valueOf(make("a board"), "flatness").core().lo, 0.6);
  EXPECT_NEAR(valueOf(make("a flat board"), "slenderness").core().lo, valueOf(make("a board"), "slenderness").core().lo, 1e-12);
}

// A part made from words is found by the same words.
TEST(PartFromWords, FoundByItsOwnWords) {
  for (const char* words : {"a slightly bent cylinder", "a very bent cylinder", "a very twisted box",
                            "an extremely tapered cone", "a long, slightly twisted rod", "a very round sphere",
                            "a flat disc", "a moderately bent and very twisted plate",
                            // a plain adjective beside a noun condition it meets at 1
                            "a flat board", "a pointed cone", "a long board",
                            // one extent beside the noun's proportions
                            "a wide rod", "a tall plate", "a thin stick"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_GE(scoreDescriptors(q, describePart(make(words))).score, 0.9) << words;
  }
  // And ranks above the other words' parts.
  const LinguisticQuery very = parseLinguisticQuery("find a very bent cylinder", v());
  EXPECT_GT(scoreDescriptors(very, describePart(make("a very bent cylinder"))).score,
            scoreDescriptors(very, describePart(make("a slightly bent cylinder"))).score);
}

// A noun's defaults score the expected membership of a part's value, not S: a knob is small, and
// "a slightly flat knob" (its size fuzzy through a2, narrow beside "small") is wholly small. S
// gave it |A∩B| / |B| = 0.053 and its words did not find it. What the words say is still S.
TEST(PartFromWords, NounDefaultsScoreAFuzzyValueByItsExpectedMembership) {
  const FuzzyPart knob = make("a slightly flat knob");
  const FuzzyNumber size = valueOf(knob, "size");
  ASSERT_FALSE(size.isCrisp());
  const FuzzyNumber knobSize = FuzzyNumber::trapezoidal(0, 0, 0.3, 0.45);
  ASSERT_LE(size.support().hi, knobSize.core().hi);
  EXPECT_LT(similarity(size, knobSize), 0.2);
  EXPECT_EQ(scoreDescriptors(parseLinguisticQuery("find a slightly flat knob", v()), describePart(knob)).score, 1.0);
  // Said, "small" scores the same value by S, and the knob's own "small" default by its expected
  // membership: the words' set is wider than the value, so S is below 1 while the default is 1.
  const QueryScore said = scoreDescriptors(parseLinguisticQuery("find a small knob", v()), describePart(knob));
  const FuzzyNumber small = v().plainSet(*v().adjective("small"));
  EXPECT_NEAR(said.score, similarity(size, small), 1e-12);
  EXPECT_LT(said.score, 1.0);
}

// A plain adjective beside a noun condition the words keep: the part takes a degree where both
// conditions are highest; one extent beside the noun's proportions scales the whole part.
TEST(PartFromWords, PlainAdjectivesTakeADegreeTheirNounAllows) {
  // "a tapered cylinder": the cylinder's taper trap(0, 0, 0.2, 0.4) falls as "tapered" rises; the
  // part sits where they cross, and its words score it there (the most the two give together).
  const FuzzyNumber taper = valueOf(make("a tapered cylinder"), "taperness");
  ASSERT_TRUE(taper.isCrisp());
  const double t = taper.core().lo;
  EXPECT_GT(t, 0.3);
  EXPECT_LT(t, 0.4);
  const FuzzyNumber tapered = v().plainSet(*v().adjective("tapered"));
  const FuzzyNumber cylinderTaper = FuzzyNumber::trapezoidal(0, 0, 0.2, 0.4);
  EXPECT_NEAR(tapered.membership(t), cylinderTaper.membership(t), 1e-9);
  // The query scores the two relative to where they meet (LinguisticQuery,
  // APlainWordCappedByItsNounScoresRelativeToTheirMeeting): the part is as tapered as the two
  // allow together, so its words score it 1; no other taper scores more.
  const LinguisticQuery q = parseLinguisticQuery("find a tapered cylinder", v());
  const auto scoreOf = [&](const FuzzyPart& p) { return scoreDescriptors(q, describePart(p)).score; };
  const double own = scoreOf(make("a tapered cylinder"));
  EXPECT_NEAR(own, 1.0, 1e-6);
  const double h = heightOfIntersection(tapered, cylinderTaper);
  EXPECT_NEAR(tapered.membership(t), h, 1e-6);
  for (double other : {0.1, 0.2, 0.25, 0.35, 0.45}) {
    FuzzyPart p = make("a tapered cylinder");
    p.kx = p.ky = FuzzyNumber::crisp(-other);
    EXPECT_GE(own, scoreOf(p)) << other;
    EXPECT_NEAR(scoreOf(p), std::min(1.0, std::min(tapered.membership(other), cylinderTaper.membership(other)) / h), 1e-9)
        << other;
  }
  // Where the two cores meet, the middle of where both are 1: "a long board" is as long as a board.
  const FuzzyNumber slender = valueOf(make("a long board"), "slenderness");
  EXPECT_NEAR(v().plainSet(*v().adjective("long")).membership(slender.core().lo), 1.0, 1e-9);
  // "a wide rod" is a thicker rod, its proportions those of "a rod".
  for (const char* d : {"elongation", "flatness", "slenderness"})
    EXPECT_NEAR(valueOf(make("a wide rod"), d).core().lo, valueOf(make("a rod"), d).core().lo, 1e-9) << d;
  EXPECT_GT(valueOf(make("a wide rod"), "width").core().lo, valueOf(make("a rod"), "width").core().lo);
  // A proportion the words say is kept the same way: "a short thick cylinder" is as short as "a
  // short cylinder" (thickening its section alone left it long: slenderness 0.42, not 0.05), and
  // as thick as "a thick cylinder"; both words score 1 for the part.
  for (const char* d : {"elongation", "flatness", "slenderness"})
    EXPECT_NEAR(valueOf(make("a short thick cylinder"), d).core().lo, valueOf(make("a short cylinder"), d).core().lo,
                1e-9) << d;
  EXPECT_NEAR(valueOf(make("a short thick cylinder"), "thickness").core().lo,
              valueOf(make("a thick cylinder"), "thickness").core().lo, 1e-9);
}

// A base beside a height: the sides across the z axis, the height along it. A square base of a
// noun alike across z is one role, so both sides are the same fuzzy number; a wedge's (tapered
// along one axis) takes both sides as two roles.
TEST(PartFromWords, ABaseSetsTheSidesAcrossTheHeight) {
  const auto extents = [](const FuzzyPart& p) {
    const PlacedSuperquadric core = p.coreRepresentative();
    const double s = 2 * core.placement.scale, a = core.params.a1;
    return std::array<double, 3>{s * a * taperedHalfWidthFactor(core.params.eps1, core.params.kx),
                                 s * a * core.params.a2 * taperedHalfWidthFactor(core.params.eps1, core.params.ky),
                                 s * a * core.params.a3};
  };
  for (const char* text : {"a pyramid, base 2 x 2, height 2.4", "a wedge, base 2 x 2, height 2.4"}) {
    const std::array<double, 3> e = extents(make(text));
    EXPECT_NEAR(e[0], 2, 1e-9) << text;
    EXPECT_NEAR(e[1], 2, 1e-9) << text;
    EXPECT_NEAR(e[2], 2.4, 1e-9) << text;
  }
  const std::array<double, 3> box = extents(make("a box, base 4 x 2, height 1"));
  EXPECT_NEAR(std::max(box[0], box[1]), 4, 1e-9);
  EXPECT_NEAR(std::min(box[0], box[1]), 2, 1e-9);
  EXPECT_NEAR(box[2], 1, 1e-9);
  // The square pyramid's two sides are one number: its words score it 1 on each.
  const FuzzyPart pyramid = make("a pyramid, base 2 x 2, height 2.4");
  EXPECT_EQ(valueOf(pyramid, "thickness"), valueOf(pyramid, "width"));
}

// A number between "a" and the noun is the noun's longest extent: a cube's side, a ball's
// diameter, a rod's length, a disc's diameter (the noun's proportions kept).
TEST(PartFromWords, ANumberBeforeTheNounIsItsLongestExtent) {
  const auto longest = [](const FuzzyPart& p) {
    const PlacedSuperquadric core = p.coreRepresentative();
    const double a = core.params.a1;
    return 2 * core.placement.scale * std::max({a, a * core.params.a2, a * core.params.a3});
  };
  for (const auto& [text, extent] : std::vector<std::pair<const char*, double>>{
           {"a 4 cube", 4}, {"a 2 unit ball", 2}, {"a 6 rod", 6}, {"a 2 disc", 2}, {"an 8 cylinder", 8}})
    EXPECT_NEAR(longest(make(text)), extent, 1e-9) << text;
  const FuzzyPart cube = make("a 4 cube");
  EXPECT_EQ(cube.a2, FuzzyNumber::crisp(1.0));
  EXPECT_EQ(cube.a3, FuzzyNumber::crisp(1.0));
  const FuzzyPart rod = make("a 6 rod");
  EXPECT_GT(rod.a3.core().lo, 1.0);  // still a rod: the length along its axis
}

// Measures set the extents they name: "a pole about 10 long" has a fuzzy length of about 10.
TEST(PartFromWords, MeasuresSetTheExtents) {
  const FuzzyPart pole = make("a thin pole about 10 long");
  const PlacedSuperquadric core = pole.coreRepresentative();
  EXPECT_NEAR(2 * core.placement.scale * core.params.a1 * core.params.a3, 10, 1e-9);
  const FuzzyNumber length = valueOf(pole, "length");
  EXPECT_NEAR(length.core().lo, extentDegree(10), 1e-9);
  EXPECT_NEAR(length.support().lo, extentDegree(9), 1e-9);
  EXPECT_NEAR(length.support().hi, extentDegree(11), 1e-9);
  // "thin" is the thickness: both axes of the round section follow it.
  EXPECT_EQ(pole.a2, FuzzyNumber::crisp(1.0));
  EXPECT_LT(2 * core.placement.scale * core.params.a1, 0.3);
  // A board's three sides on the plate's axes, the shortest its thickness.
  const FuzzyPart board = make("a board 8 long, 1 wide, 0.2 thick");
  const std::vector<DescriptorValue> d = describePart(board);
  EXPECT_NEAR(d[descriptorIndex("length")].value.core().lo, extentDegree(8), 1e-9);
  EXPECT_NEAR(d[descriptorIndex("width")].value.core().lo, extentDegree(1), 1e-9);
  EXPECT_NEAR(d[descriptorIndex("thickness")].value.core().lo, extentDegree(0.2), 1e-9);
  // A disc's diameter sets both axes of its round face; its thickness the third.
  const FuzzyPart puck = make("a puck 3 in diameter and 1 thick");
  const PlacedSuperquadric p = puck.coreRepresentative();
  EXPECT_NEAR(2 * p.params.a1, 3, 1e-9);
  EXPECT_NEAR(2 * p.params.a1 * p.params.a2, 3, 1e-9);
  EXPECT_NEAR(2 * p.params.a1 * p.params.a3, 1, 1e-9);
  // The example: a very twisted box about 3 units long.
  const FuzzyPart box = make("a very twisted box about 3 units long");
  EXPECT_NEAR(valueOf(box, "length").core().lo, extentDegree(3), 1e-9);
  EXPECT_GT(valueOf(box, "twistness").core().lo, 0.5);
  // And each is found by its own words. (Plain dimension adjectives, "thin", "tall", score as
  // "big" does: the paper's S of a narrow value against the plain set μ(d) = d is well below 1;
  // their measures score 1.)
  for (const char* words : {"a board 8 long, 1 wide, 0.2 thick", "a puck 3 in diameter and 1 thick",
                            "a very twisted box about 3 units long", "a rod 6 long and 0.2 across",
                            "a ball of radius 5", "a cube 2 units on a side"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_GE(scoreDescriptors(q, describePart(make(words))).score, 0.9) << words;
  }
  const QueryScore thin = scoreDescriptors(parseLinguisticQuery("find a thin pole about 10 long", v()), describePart(pole));
  bool measured = false;
  for (const ConditionScore& c : thin.explain) {
    if (c.text != "about 10 long") continue;
    measured = true;
    EXPECT_NEAR(c.score, 1.0, 1e-12);
  }
  EXPECT_TRUE(measured) << "the explain names the measure";
  EXPECT_GT(thin.score, 0.8);
}

// The round trip over every noun with a shape and a set of measures (issue's property: a part
// made from words is found by them at 0.9 or more): one extent, two, three, sides, a radius,
// numbers as phrases, and two whose roles contradict the numbers' order ("with diameter 2 and
// length 1" on a box is read sorted; on a cylinder the length is its axis). Nouns that keep a
// size condition (a knob is small) are left out: a knob 4 tall is no knob, and its words say so.
TEST(PartFromWords, EveryNounTakesMeasuresItsWordsFind) {
  const std::vector<std::string> measures = {
      "2 long", "3 across", "0.5 thick", "4 tall", "2 across and 5 long", "with diameter 2 and length 1",
      "about 10 long", "between 3 and 4 wide", "4 x 2 x 1", "1 across and 0.2 thick", "5 long and 0.5 wide",
      "3 long, 2 wide and 1 thick", "0.3 thick and 4 across", "with a radius of 1", "exactly 2 long",
      "8 long with a 0.6 by 1 cross section", "of 6 length"};
  int nouns = 0;
  for (const std::string& noun : v().nounWords()) {
    const Noun* n = v().noun(noun);
    if (!n || n->params.is_null()) continue;
    if (std::any_of(n->conditions.begin(), n->conditions.end(), [](const NounCondition& c) { return c.descriptor == "size"; }))
      continue;
    ++nouns;
    for (const std::string& m : measures) {
      const std::string words = "a " + noun + " " + m;
      const LinguisticQuery q = parseLinguisticQuery(words, v());
      EXPECT_GE(scoreDescriptors(q, describePart(make(words))).score, 0.9) << words;
    }
  }
  EXPECT_GT(nouns, 40);
}

// A measured length of a cylinder, a rod or a cone runs along its axis even when it is shorter
// than the diameter: the part made is a stubby cylinder, and its words find it (they read the
// axial length, the height; they read the longest extent, its diameter, before, and scored 0).
TEST(PartFromWords, AStubbyCylinderIsFoundByItsMeasures) {
  for (const char* words : {"a cylinder with diameter 2 and length 1", "a cylinder 2 across and 1 long",
                            "a rod 0.5 long and 3 across", "a cylinder 2 across and 10 long", "a board 8 long and 1 wide"}) {
    const LinguisticQuery q = parseLinguisticQuery(words, v());
    EXPECT_GE(scoreDescriptors(q, describePart(make(words))).score, 0.9) << words;
  }
  const FuzzyPart stubby = make("a cylinder with diameter 2 and length 1");
  EXPECT_NEAR(valueOf(stubby, "height").core().lo, 0.5, 0.05);  // d(1) = 1 / 2
  EXPECT_NEAR(valueOf(stubby, "length").core().lo, 2.0 / 3, 0.05);  // its diameter, d(2)
}

// An extent word keeps the axes in their roles (shortest, middle, longest), so the extent read back
// is the one the words set.
TEST(PartFromWords, ExtentWordsKeepTheAxesInTheirRoles) {
  // A thickness past the diameter scales the whole disc: its proportions are a disc's.
  const FuzzyPart thick = make("an extremely thick disc");
  EXPECT_EQ(valueOf(thick, "flatness"), valueOf(make("a disc"), "flatness"));
  EXPECT_TRUE(thick.a1.isCrisp() && thick.a2.isCrisp() && thick.a3.isCrisp());
  EXPECT_FALSE(thick.scale.isCrisp());
  // A width below a puck's thickness the same way; one above it keeps the thickness.
  EXPECT_EQ(valueOf(make("an extremely narrow puck"), "flatness"), valueOf(make("a puck"), "flatness"));
  // The round face's second axis follows a1's spread with ratio 1, not a spread of its own.
  const FuzzyPart narrow = make("a moderately narrow puck");
  EXPECT_EQ(narrow.a2, FuzzyNumber::crisp(1.0));
  for (const char* words : {"an extremely thick disc", "an extremely narrow puck", "a moderately narrow puck",
                            "an extremely broad pipe", "a very short plate", "a somewhat wide pyramid",
                            "a very thick double pyramid"}) {
    const LinguisticQuery q = parseLinguisticQuery(words, v());
    EXPECT_GE(scoreDescriptors(q, describePart(make(words))).score, 0.9) << words;
  }
}

// Words on the traverse section set eps2 alone ("a cylindrical plate" keeps the plate's eps1, so its
// ends stay flat), after the whole shape's words. They set nothing before: the part was the noun.
// Beside a box, which keeps its squareness, the ends may only sharpen towards it
// (ExponentWordsMeetANounsKeptShape): they stay flat.
TEST(PartFromWords, SectionWordsSetTheSectionAlone) {
  const FuzzyPart box = make("a box"), cylindrical = make("a cylindrical box");
  EXPECT_EQ(make("a cylindrical plate").eps1, make("a plate").eps1);
  EXPECT_NE(make("a cylindrical plate").eps2, make("a plate").eps2);
  ASSERT_TRUE(cylindrical.eps1.isCrisp());
  EXPECT_LE(cylindrical.eps1.core().hi, box.eps1.core().lo);
  EXPECT_NE(cylindrical.eps2, box.eps2);
  // The same rule as roundness's (max(0.05, d)), on eps2 alone: the same degrees. (On a rod,
  // whose roundness the words replace: a box keeps its squareness beside them, and its part
  // meets it, ExponentWordsMeetANounsKeptShape.)
  EXPECT_NEAR(similarity(valueOf(make("a cylindrical rod"), "section-roundness"), valueOf(make("a round rod"), "roundness")),
              1.0, 1e-9);
  EXPECT_NEAR(similarity(valueOf(make("a very tubular rod"), "section-roundness"),
                         valueOf(make("a very round rod"), "roundness")),
              1.0, 1e-9);
  // A section word acts after a word on the whole shape, whatever the text's order.
  EXPECT_EQ(make("a cylindrical square rod").eps2, make("a cylindrical rod").eps2);
  EXPECT_EQ(make("a cylindrical square rod").eps1, make("a square rod").eps1);
  EXPECT_NE(make("a square rod").eps1, make("a rod").eps1);
}

// On a flat noun "round" and "square" make the outline: a round plate is a plate with a round
// section and flat faces (eps1 kept), found by the same words.
TEST(PartFromWords, OutlineWordsOnAFlatNounSetItsSection) {
  const FuzzyPart plate = make("a plate"), round = make("a round plate");
  EXPECT_EQ(round.eps1, plate.eps1);
  EXPECT_EQ(round.eps2, make("a cylindrical plate").eps2);  // section-roundness said outright
  EXPECT_EQ(round.a3, plate.a3);
  EXPECT_GT(valueOf(round, "section-roundness").core().lo, valueOf(plate, "section-roundness").core().hi + 0.3);
  EXPECT_EQ(make("a square disc").eps1, make("a disc").eps1);
  // A ball's "round" is still the whole shape's.
  EXPECT_EQ(make("a round ball").eps1, make("a round ball").eps2);
  EXPECT_EQ(make("a round ball").eps1, FuzzyNumber::crisp(1.0));  // round makes round: ε = 1
  const FuzzyPart squareBall = make("a square ball");
  EXPECT_EQ(squareBall.eps1, squareBall.eps2);
  EXPECT_NE(squareBall.eps1, make("a ball").eps1);
}

TEST(PartFromWords, AdjectivesActInATableOrder) {
  // The bend is measured on the final length: "bent long" equals "long bent".
  const FuzzyPart a = make("a slightly bent long rod"), b = make("a long slightly bent rod");
  EXPECT_EQ(a.kv, b.kv);
  EXPECT_EQ(a.a3, b.a3);
}

// Adjectives after the noun, an intensity after its adjective and a comma before them read as a
// query reads them: the same part as the words in the usual order.
TEST(PartFromWords, AdjectivesAfterTheNounAndIntensitiesAfterTheirAdjective) {
  const auto same = [](const std::string& a, const std::string& b) {
    EXPECT_EQ(partToJson(make(a)), partToJson(make(b))) << a << " / " << b;
  };
  same("a rod bent slightly", "a slightly bent rod");
  same("a cylinder slightly bent", "a slightly bent cylinder");
  same("a box, very twisted", "a very twisted box");
  same("a box twisted a little", "a slightly twisted box");
  same("a bar bent a lot and twisted slightly", "a very bent, slightly twisted bar");
  same("a pole about 10 long, slightly bent", "a slightly bent pole about 10 long");
  same("a cylinder, slightly bent, with sharp edges", "a slightly bent cylinder with sharp edges");
  // The words still end with the description: a second noun is no part.
  EXPECT_NE(errorOf("a cylinder slightly bent box").find("the end of the description"), std::string::npos);
}

// The exponent words invert their descriptor exactly (ε = d for roundness, 1 − d for squariness)
// down to the smallest exponent, 0.01, where the image gathers what lies below it (the extension
// principle: its membership is the highest of those degrees).
TEST(PartFromWords, ExponentWordsInvertTheirDescriptorExactly) {
  EXPECT_EQ(make("a moderately round ball").eps1, FuzzyNumber::trapezoidal(0.3, 0.45, 0.6, 0.75));
  EXPECT_EQ(make("a moderately square box").eps2, FuzzyNumber::trapezoidal(0.25, 0.4, 0.55, 0.7));
  const auto expectPoints = [](const FuzzyNumber& got, const std::vector<Breakpoint>& want) {
    ASSERT_EQ(got.breakpoints().size(), want.size()) << toJson(got);
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_NEAR(got.breakpoints()[i].x, want[i].x, 1e-12) << i;
      EXPECT_NEAR(got.breakpoints()[i].mu, want[i].mu, 1e-12) << i;
    }
  };
  // (A set starts at membership 0: a jump is two points at one x.)
  expectPoints(make("an extremely square box").eps1, {{0.01, 0}, {0.01, 1}, {0.05, 1}, {0.2, 0}});
  // slightly: trap(0, 0.1, 0.25, 0.4); the degrees under 0.01 (membership up to 0.1) gather at it.
  // (On a ball: a box keeps its square shape beside a round word, ExponentWordsMeetANounsKeptShape.)
  expectPoints(make("a slightly round ball").eps1, {{0.01, 0}, {0.01, 0.1}, {0.1, 1}, {0.25, 1}, {0.4, 0}});
  const LinguisticQuery q = parseLinguisticQuery("find a moderately round shape", v());
  EXPECT_NEAR(scoreDescriptors(q, describePart(make("a moderately round ball"))).score, 1.0, 1e-9);
}

// An exponent word beside a noun whose exponent shape the words keep (a box is its squareness,
// an octahedron its bevels): the word's own shape scored 0 for the noun, and the words did not
// find their part at all. The exponents now sit where the words score the part highest along
// the word's path (eps1 = eps2 = e; eps2 alone for a section word).
TEST(PartFromWords, ExponentWordsMeetANounsKeptShape) {
  for (const char* text : {"a round box", "a round octahedron", "a boxy ellipsoid", "a cylindrical box",
                           "a slightly round box"}) {
    const LinguisticQuery q = parseLinguisticQuery(text, v());
    const FuzzyPart part = make(text);
    const double own = scoreDescriptors(q, describePart(part)).score;
    EXPECT_GT(own, 0.2) << text;
    // The words score it relative to the most the word and the noun give together (LinguisticQuery,
    // AnExponentWordBesideANounsShapeScoresRelativeToTheirMeeting): 1, or within the grid's reach.
    EXPECT_GT(own, 0.95) << text;
    const bool section = std::string(text) == "a cylindrical box";
    for (double e = 0.01; e <= 4.0; e += 0.01) {
      FuzzyPart other = part;
      other.eps2 = FuzzyNumber::crisp(e);
      if (!section) other.eps1 = other.eps2;
      ASSERT_GE(own + 1e-3, scoreDescriptors(q, describePart(other)).score) << text << " at " << e;
    }
  }
  // A section word moves the section (eps2) and the ends (eps1) that the box's squareness reads.
  EXPECT_NE(make("a cylindrical box").eps2, make("a box").eps2);
  // Where the noun's shape is replaced or met, the word's own set stands.
  EXPECT_FALSE(make("a very boxy ball").eps1.isCrisp());
  EXPECT_FALSE(make("a slightly round ball").eps1.isCrisp());
  EXPECT_EQ(make("a round ball").eps1, make("a ball").eps1);
}

// "with rounded edges" sets the exponents as the adjective before the noun does ("a rounded
// box"): the vocabulary's edge set, between the box's square and a round shape; the words find
// that part with a score of 1.
TEST(PartFromWords, EdgeWordsRoundTheEdges) {
  const FuzzyPart with = make("a box with rounded edges");
  EXPECT_EQ(with.eps1, make("a rounded box").eps1);
  EXPECT_EQ(with.eps2, make("a rounded box").eps2);
  EXPECT_EQ(with.a3, make("a box").a3);
  EXPECT_EQ(with.eps1, v().edgeSet());  // roundness is ε itself below 1
  EXPECT_NE(make("a rounded ball").eps1, with.eps1);  // a ball has no edges: plain "rounded"
  EXPECT_EQ(make("a cube with very soft corners").eps1, make("a very soft cube").eps1);
  EXPECT_EQ(make("a cube with a rounded edge").eps1, make("a rounded cube").eps1);
  // With an intensity the same: "a somewhat softened box" (it scored 0.43 when the intensity made
  // it a degree of the whole shape's roundness, against the box's squareness).
  EXPECT_EQ(make("a somewhat softened box").eps1, make("a box with somewhat softened edges").eps1);
  for (const char* words : {"a box with rounded edges", "a rounded box", "a cube with softened corners",
                            "a filleted cube", "a somewhat softened box", "a very rounded cube"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_NEAR(scoreDescriptors(q, describePart(make(words))).score, 1.0, 1e-9) << words;
  }
  EXPECT_NE(errorOf("a cube with bent edges").find("the shape of its edges"), std::string::npos);
  EXPECT_NE(errorOf("a cube with rounded").find("the shape of its edges"), std::string::npos);
}

// Edges are the noun's exponents below 1: a cylinder's rims (eps1) round or sharpen and its
// round section (eps2 = 1) stays; sharp edges take the sharp edge set ("sharp" is no taper
// there); the words after the noun win over a shape word before it. Every one is found by its
// own words with a score of 1.
TEST(PartFromWords, EdgesAreTheNounsExponentsBelowOne) {
  const FuzzyPart cylinder = make("a cylinder with rounded edges");
  EXPECT_EQ(cylinder.eps1, v().edgeSet());
  EXPECT_EQ(cylinder.eps2, make("a cylinder").eps2);
  EXPECT_EQ(make("a rounded cylinder").eps1, v().edgeSet());
  EXPECT_EQ(make("a rounded cylinder").eps2, make("a cylinder").eps2);
  const FuzzyPart sharp = make("a cylinder with sharp edges");
  EXPECT_EQ(sharp.eps2, make("a cylinder").eps2);
  EXPECT_LE(sharp.eps1.support().hi, 0.15 + 1e-12);
  EXPECT_EQ(sharp.kx, make("a cylinder").kx);  // no taper
  const FuzzyPart box = make("a round box with sharp edges");
  EXPECT_EQ(box.eps1, sharp.eps1);
  EXPECT_EQ(box.eps2, sharp.eps1);
  EXPECT_EQ(make("a rounded box with sharp corners").eps1, sharp.eps1);
  for (const char* words : {"a cylinder with rounded edges", "a rounded cylinder", "a cylinder with sharp edges",
                            "a cone with soft edges", "a box with sharp corners", "a disc with rounded edges",
                            "a cylinder 6 long with sharp edges", "a cube with moderately rounded corners",
                            "a ball with sharp edges"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_NEAR(scoreDescriptors(q, describePart(make(words))).score, 1.0, 1e-9) << words;
  }
  // The words tell the rims apart: a plain cylinder has sharp edges and no rounded ones.
  const auto score = [](const std::string& query, const std::string& part) {
    return scoreDescriptors(parseLinguisticQuery(query, v()), describePart(make(part))).score;
  };
  EXPECT_NEAR(score("a cylinder with sharp edges", "a cylinder"), 1.0, 1e-9);
  EXPECT_EQ(score("a cylinder with rounded edges", "a cylinder"), 0.0);
  EXPECT_EQ(score("a cylinder with sharp edges", "a cylinder with rounded edges"), 0.0);
}

// An adjective with its own set ("truncated": a middle of taperness) makes the part its set says,
// and the plain words find it at 1; a truncated cone keeps the cone's other conditions.
TEST(PartFromWords, MiddleAdjectivesRoundTripPlain) {
  const FuzzyPart truncated = make("a truncated cone");
  EXPECT_EQ(truncated.kx, negate(*v().adjective("truncated")->set));  // kx = −d
  EXPECT_EQ(truncated.eps2, make("a cone").eps2);
  for (const char* words : {"a truncated cone", "a blunt pyramid", "a truncated cylinder", "a frustum"}) {
    const LinguisticQuery q = parseLinguisticQuery(std::string("find ") + words, v());
    EXPECT_NEAR(scoreDescriptors(q, describePart(make(words))).score, 1.0, 1e-9) << words;
  }
  // A sharp cone is no truncated one.
  EXPECT_EQ(scoreDescriptors(parseLinguisticQuery("a truncated cone", v()), describePart(make("a cone"))).score, 0.0);
}

// The extreme intensities reach the end of the degrees, a size, ratio or exponent no part has: the
// part takes the set cut at the descriptor's degree domain (0.99 or 0.01; an exponent at 0.01),
// which the search reads the words over too (withinDegreeDomains), so the words find it at 1. As
// the paper's S of the sets as written, 0.9 or more.
TEST(PartFromWords, ExtremeIntensitiesAreFoundByTheirWords) {
  for (const char* words : {"an extremely large ball", "an extremely small disc", "an extremely long rod",
                            "an extremely flat box", "an extremely thin rod", "an extremely tiny plank",
                            "an extremely elongated ellipsoid", "a slightly tiny ball", "a very enormous rod",
                            "an extremely square box", "a very boxy pillar", "a cube with very sharp edges"}) {
    const LinguisticQuery q = parseLinguisticQuery(words, v());
    const FuzzyPart part = make(words);
    const QueryScore s = scoreDescriptors(q, describePart(part));
    std::string why;
    for (const ConditionScore& c : s.explain) why += c.text + "=" + std::to_string(c.score) + " ";
    EXPECT_GE(s.score, 0.9) << words << ": " << why;
    const QueryScore read = scoreDescriptors(withinDegreeDomains(q), describePart(part));
    EXPECT_EQ(read.score, 1.0) << words;
    EXPECT_EQ(read.coverage, 1.0) << words;
  }
  // The other end: "slightly" starts at 0, where no size is.
  // A cylinder's edges are its eps1 alone: their degree is read over the domain before the mean
  // with the round section (edges.h). A graded exponent word replaces a round noun's shape.
  for (const char* words : {"a slightly big ball", "a slightly tall wafer", "a slightly long rod",
                            "a very short rod", "a slightly smooth box", "a very cubical barrel",
                            "a slightly smooth cylinder", "a slightly filleted disk", "a very boxy ellipsoid",
                            "a slightly cubic spheroid", "a somewhat smoothed double pyramid"}) {
    const QueryScore read =
        scoreDescriptors(withinDegreeDomains(parseLinguisticQuery(words, v())), describePart(make(words)));
    EXPECT_EQ(read.score, 1.0) << words;
  }
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
