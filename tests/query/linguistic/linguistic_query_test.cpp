// The parser of linguistic queries: every production of schema/query_grammar.ebnf, the examples
// listed there, and the errors.
#include "query/linguistic/linguistic_query.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/json/fuzzy_json.h"
#include "query/linguistic/degree_sets.h"
#include "query/linguistic/descriptors.h"
#include "query/linguistic/query_print.h"
#include "query/linguistic/vocabulary.h"
#include "tests/testing/grammar_examples.h"
#include "tests/testing/query_shapes.h"
#include "tests/testing/text_error.h"

namespace fsdb {
namespace {

using Kind = QueryCondition::Kind;

const Vocabulary& v() { return Vocabulary::builtin(); }
LinguisticQuery parse(const std::string& text) { return parseLinguisticQuery(text, v()); }

std::string errorOf(const std::string& text) {
  return test::textErrorOf(text, [](const std::string& t) { parse(t); });
}

void expectLeaf(const QueryCondition& c, const std::string& descriptor, const FuzzyNumber& set, const std::string& text) {
  EXPECT_EQ(c.kind, Kind::kDescriptor);
  EXPECT_EQ(c.descriptor, descriptor);
  EXPECT_EQ(c.set, set);
  EXPECT_EQ(c.text, text);
}

nlohmann::json meaning(const std::string& text) { return testing::queryMeaning(parse(text)); }

// The leaves of a condition, in order (a leaf is itself).
std::vector<QueryCondition> leavesOf(const QueryCondition& c) {
  if (c.kind == Kind::kDescriptor) return {c};
  std::vector<QueryCondition> out;
  for (const QueryCondition& child : c.children)
    for (QueryCondition& leaf : leavesOf(child)) out.push_back(std::move(leaf));
  return out;
}

// The measure leaves of a query: (descriptor, extent).
std::vector<std::pair<std::string, FuzzyNumber>> measuresOf(const std::string& text) {
  std::vector<std::pair<std::string, FuzzyNumber>> out;
  for (const QueryCondition& leaf : leavesOf(parse(text).root))
    if (leaf.measure) {
      EXPECT_EQ(leaf.set, extentDegreeSet(*leaf.measure)) << text;
      out.emplace_back(leaf.descriptor, *leaf.measure);
    }
  return out;
}

using Measures = std::vector<std::pair<std::string, FuzzyNumber>>;
FuzzyNumber near(double x) { return FuzzyNumber::triangular(0.9 * x, x, 1.1 * x); }

// An adjective that names a noun's shape ("cylindrical") is that noun where no noun with a shape
// of its own follows: a ball has a round section, but "a cylindrical thing" is a cylinder. Beside a
// noun with a shape it keeps its descriptor; under "not" or "or" it says something else.
// "very very long" is extremely long (query_tokens.h, readableWords), in the adjective before its
// noun, after it and in a clause; the condition's text keeps the words as written.
TEST(LinguisticQuery, ARepeatedIntensityStepsUp) {
  const auto conditions = [](const std::string& text) {
    nlohmann::json j = toJson(parse(text))["condition"];
    std::string sets;
    for (const nlohmann::json& c : j["children"]) sets += c["set"].dump();
    return sets;
  };
  EXPECT_EQ(conditions("a very very long box"), conditions("an extremely long box"));
  EXPECT_EQ(conditions("a box that is very, very long"), conditions("a box that is extremely long"));
  EXPECT_EQ(conditions("a box very very long"), conditions("a box extremely long"));
  EXPECT_NE(conditions("a very very long box"), conditions("a very long box"));
  EXPECT_EQ(toJson(parse("a very very long box"))["condition"]["children"][0]["text"], "very very long");
}

// A deformation said as a noun after "with" reads as its adjective, graded by the adjective
// before the noun; the condition's text is the phrase as written.
TEST(LinguisticQuery, AFeatureNounIsItsAdjective) {
  const auto sets = [](const std::string& text) {
    std::string out;
    const std::function<void(const nlohmann::json&)> walk = [&](const nlohmann::json& c) {
      if (c.contains("set")) out += c["descriptor"].get<std::string>() + c["set"].dump();
      if (c.contains("children"))
        for (const nlohmann::json& child : c["children"]) walk(child);
    };
    walk(toJson(parse(text))["condition"]);
    return out;
  };
  EXPECT_EQ(sets("a cylinder with a slight bend"), sets("a cylinder that is slightly bent"));
  EXPECT_EQ(sets("a box with a twist"), sets("a box that is twisted"));
  EXPECT_EQ(sets("a rod with a strong taper"), sets("a rod that is very tapered"));
  EXPECT_EQ(sets("a rod with a gentle curve"), sets("a rod that is slightly curved"));
  // A tip cut off is truncated, however it is said.
  for (const char* text : {"a cone with its top cut off", "a cone with the tip cut away", "cone with top cutted",
                           "a cone with the top removed", "a cone with the apex sliced off"})
    EXPECT_EQ(sets(text), sets("a cone that is truncated")) << text;
  // The grading word is a word of the grammar; the noun is read in its phrase only, so that
  // after "that" or "which" it routes as a verb ("rods which taper": word_routes_test).
  EXPECT_TRUE(knowsLinguisticWord("slight", v()));
  EXPECT_FALSE(knowsLinguisticWord("taper", v()));
}

TEST(LinguisticQuery, AnAdjectiveThatNamesAShapeIsItsNoun) {
  const auto nounOf = [](const std::string& text) {
    const LinguisticQuery q = parse(text);
    std::string noun;
    const std::function<void(const QueryCondition&)> find = [&](const QueryCondition& c) {
      if (!c.noun.empty() && noun.empty()) noun = c.noun;
      for (const QueryCondition& child : c.children) find(child);
    };
    find(q.root);
    return noun;
  };
  EXPECT_EQ(nounOf("a cylindrical thing"), "cylinder");
  EXPECT_EQ(nounOf("cylindrical"), "cylinder");
  EXPECT_EQ(nounOf("something conical"), "cone");
  EXPECT_EQ(nounOf("a part that is cylindrical"), "cylinder");
  EXPECT_EQ(parse("a part that is cylindrical").subject, parse("a part").subject);
  EXPECT_EQ(nounOf("a slightly bent spherical shape"), "sphere");
  EXPECT_EQ(nounOf("a pyramidal thing on a cubic thing"), "pyramid");
  EXPECT_EQ(meaning("a cylindrical thing that is slightly bent"), meaning("a cylinder that is slightly bent"));
  EXPECT_EQ(meaning("cylindrical and small")["condition"]["children"].size(), 2u);
  // Beside a noun with a shape, its descriptor: a cylindrical box has a round section.
  EXPECT_EQ(nounOf("a cylindrical box"), "box");
  bool roundSection = false;
  for (const QueryCondition& leaf : leavesOf(parse("a cylindrical box").root))
    roundSection = roundSection || leaf.descriptor == "section-roundness";
  EXPECT_TRUE(roundSection);
  EXPECT_EQ(nounOf("not cylindrical"), "");
  EXPECT_EQ(nounOf("cylindrical or conical"), "");
  EXPECT_EQ(nounOf("a very cylindrical thing"), "");  // a degree of its own: the round section
  // Each reads back from its printed text (a noun phrase is printed as modifiers, noun, clause).
  for (const char* text : {"something cubic and small that is bent", "cubic and small with squarish traverse section",
                           "a small cubic thing that is bent", "a small part that is cylindrical",
                           "something conical and very small", "a small bent spherical object that is twisted",
                           "find parts that are conical, small and bent"}) {
    const LinguisticQuery q = parse(text);
    const std::string printed = linguisticQueryText(q, v());
    LinguisticQuery again;
    ASSERT_NO_THROW(again = parse(printed)) << text << " -> " << printed;
    EXPECT_EQ(testing::queryMeaning(again), testing::queryMeaning(q)) << text << " -> " << printed;
  }
}

TEST(LinguisticQuery, MeasuresAreConditionsOnTheExtents) {
  // After a number, a dimension word; a plain number is within 10 %, a number phrase as written.
  // The length of a noun turned about its own z axis (a cylinder, a rod, a pin) is its axial
  // length, the height; elsewhere the longest extent.
  EXPECT_EQ(measuresOf("a cylinder about 10 long and 1 across"),
            (Measures{{"height", FuzzyNumber::triangular(9, 10, 11)}, {"width", near(1)}}));
  EXPECT_EQ(measuresOf("a rod 6 long and 0.2 in diameter"), (Measures{{"height", near(6)}, {"width", near(0.2)}}));
  EXPECT_EQ(measuresOf("something between 3 and 4 wide"), (Measures{{"width", FuzzyNumber::trapezoidal(3, 3, 4, 4)}}));
  EXPECT_EQ(measuresOf("a post 3 units tall"), (Measures{{"height", near(3)}}));
  EXPECT_EQ(measuresOf("a pin exactly 2 long, 0.1 thick"),
            (Measures{{"height", FuzzyNumber::crisp(2)}, {"thickness", near(0.1)}}));
  EXPECT_EQ(measuresOf("a board 8 long"), (Measures{{"length", near(8)}}));
  EXPECT_EQ(measuresOf("a box 3 long"), (Measures{{"length", near(3)}}));
  EXPECT_EQ(measuresOf("a disc 2 long"), (Measures{{"length", near(2)}}));
  EXPECT_EQ(measuresOf("something 5 long"), (Measures{{"length", near(5)}}));
  // Before a number, a dimension noun; a radius is half a width. A stubby cylinder's length is
  // along its axis, shorter than its diameter.
  EXPECT_EQ(measuresOf("a cylinder with diameter 2 and length 1"), (Measures{{"width", near(2)}, {"height", near(1)}}));
  EXPECT_EQ(measuresOf("a ball of radius 5"), (Measures{{"width", near(10)}}));
  EXPECT_EQ(measuresOf("a disc with a radius of about 1"), (Measures{{"width", FuzzyNumber::triangular(1.8, 2, 2.2)}}));
  EXPECT_EQ(measuresOf("sphere, diameter 0.2"), (Measures{{"width", near(0.2)}}));
  // Three numbers are the sorted extents; a side is all three.
  EXPECT_EQ(measuresOf("a box 4 by 2 by 1"),
            (Measures{{"thickness", near(1)}, {"width", near(2)}, {"length", near(4)}}));
  EXPECT_EQ(measuresOf("a plate 4 x 4 x 0.1 units"),
            (Measures{{"thickness", near(0.1)}, {"width", near(4)}, {"length", near(4)}}));
  EXPECT_EQ(measuresOf("a cube 4 units on a side"),
            (Measures{{"thickness", near(4)}, {"width", near(4)}, {"length", near(4)}}));
  // Two numbers and a section word are the section across the length: the two shorter extents.
  EXPECT_EQ(measuresOf("a beam 8 long with a 0.6 by 1 cross section"),
            (Measures{{"length", near(8)}, {"thickness", near(0.6)}, {"width", near(1)}}));
  EXPECT_EQ(measuresOf("a bar with a 2 x 0.5 profile"), (Measures{{"thickness", near(0.5)}, {"width", near(2)}}));
  EXPECT_EQ(measuresOf("a board with a 1 by 0.2 cross-section"),
            (Measures{{"thickness", near(0.2)}, {"width", near(1)}}));
  EXPECT_THROW(parse("a box 3 by 2"), Error);  // two numbers and no section: which two extents is unsaid
  // One number of a section, before or after its word: both shorter extents.
  EXPECT_EQ(measuresOf("a bar, section 0.4, length 6"),
            (Measures{{"thickness", near(0.4)}, {"width", near(0.4)}, {"height", near(6)}}));
  EXPECT_EQ(measuresOf("a beam with a 0.5 cross section"), (Measures{{"thickness", near(0.5)}, {"width", near(0.5)}}));
  // A base beside a height: the three sorted, so that a flat part's base is its two longer
  // sides; alone, the width between its sides (which extents they are depends on the height).
  EXPECT_EQ(measuresOf("a wedge, base 2 x 2, height 1"),
            (Measures{{"thickness", near(1)}, {"width", near(2)}, {"length", near(2)}, {"height", near(1)}}));
  EXPECT_EQ(measuresOf("a pyramid, 1 x 1 base, 6 tall"),
            (Measures{{"thickness", near(1)}, {"width", near(1)}, {"length", near(6)}, {"height", near(6)}}));
  // In a "with" clause the base is its width beside the height (both hold either way).
  EXPECT_EQ(measuresOf("a pyramid with 1 x 1 base, 6 tall"), (Measures{{"width", near(1)}, {"height", near(6)}}));
  EXPECT_EQ(measuresOf("a pyramid, base 2 by 3"),
            (Measures{{"width", FuzzyNumber::trapezoidal(near(2).support().lo, 2, 3, near(3).support().hi)}}));
  EXPECT_EQ(measuresOf("a cone with base diameter 2 and height 3"), (Measures{{"width", near(2)}, {"height", near(3)}}));
  EXPECT_EQ(measuresOf("a cone with 2 base diameter and height 3"), (Measures{{"width", near(2)}, {"height", near(3)}}));
  // A number between "a" and the noun is its longest extent (a cube's side, a ball's diameter, a
  // rod's length: along its axis), units or not; without "a" a number before a noun is a count.
  EXPECT_EQ(measuresOf("a 4 cube"), (Measures{{"length", near(4)}}));
  EXPECT_EQ(measuresOf("a 2 unit ball"), (Measures{{"height", near(2)}}));
  EXPECT_EQ(measuresOf("an 8 rod that is slightly bent"), (Measures{{"height", near(8)}}));
  EXPECT_EQ(measuresOf("a 2 disc"), (Measures{{"length", near(2)}}));
  EXPECT_THROW(parse("4 cube"), Error);
  EXPECT_THROW(parse("a 4"), Error);
  // A dimension noun after its number, "of" before it, as a non-native speaker may order them.
  EXPECT_EQ(measuresOf("rod thin straight of 6 length"), (Measures{{"height", near(6)}}));
  EXPECT_EQ(measuresOf("a box of 2 width"), (Measures{{"width", near(2)}}));
  EXPECT_EQ(measuresOf("a plate 0.1 thickness"), (Measures{{"thickness", near(0.1)}}));
  // With the noun's own conditions and a clause: all of them hold (min).
  const LinguisticQuery q = parse("a cylinder 6 long that is slightly bent");
  ASSERT_EQ(q.root.kind, Kind::kAnd);
  EXPECT_EQ(leavesOf(q.root).size(), 3u + 1u + 1u);  // cylinder's three, the length, the bend
  // A distance before a direction is still a relation, not a measure.
  EXPECT_EQ(parse("find a sphere about 3 units above a box").root.kind, Kind::kRelation);
}

// Edges ("with rounded edges", "a rounded box", "with sharp edges"): a condition on the edge
// descriptor; plain the vocabulary's edge or sharp set, with an intensity its set (mirrored for
// sharp edges); for a box, whose both exponents are edges, that set itself.
TEST(LinguisticQuery, EdgeWordsSayTheShapeOfTheEdges) {
  using Edges = QueryCondition::Edges;
  const auto edgeLeaf = [](const std::string& text) {
    for (const QueryCondition& leaf : leavesOf(parse(text).root))
      if (leaf.edges != Edges::kNone) return leaf;
    ADD_FAILURE() << "no edge condition in " << text;
    return QueryCondition{};
  };
  const Vocabulary& v = Vocabulary::builtin();
  for (const char* text : {"a cube with round edges", "a cube with rounded corners", "a box with a rounded edge",
                           "a rounded box", "a filleted cube", "a radiused box", "a box with smooth edges",
                           "cube with round edge"}) {
    const QueryCondition c = edgeLeaf(text);
    EXPECT_EQ(c.descriptor, "roundness") << text;
    EXPECT_EQ(c.set, v.edgeSet()) << text;
    EXPECT_FALSE(c.edgeDegree) << text;  // turned for its noun
  }
  EXPECT_EQ(edgeLeaf("a cube with round edges").edges, Edges::kNamed);
  EXPECT_EQ(edgeLeaf("a rounded box").edges, Edges::kBeforeNoun);
  EXPECT_EQ(edgeLeaf("a cube with very rounded edges").set, *v.intensity("very"));
  EXPECT_EQ(edgeLeaf("a cube with round edges").text, "round edges");
  // Sharp edges: "sharp" before a noun is a taper, before an edge word the sharp edge set.
  for (const char* text : {"a box with sharp edges", "a cube with square corners", "a box with a sharp edge"}) {
    const QueryCondition c = edgeLeaf(text);
    EXPECT_EQ(c.descriptor, "roundness") << text;
    EXPECT_EQ(c.set, v.sharpEdgeSet()) << text;
  }
  EXPECT_EQ(edgeLeaf("a box with very sharp edges").set, mirroredDegrees(*v.intensity("very")));
  for (const QueryCondition& leaf : leavesOf(parse("a box with sharp edges").root))
    EXPECT_NE(leaf.descriptor, "taperness");
  // With an intensity too: "a very rounded box" is a box with very rounded edges (it was a degree
  // of roundness of its own, which the box's squareness vetoed: its own part scored 0.43).
  EXPECT_EQ(edgeLeaf("a very rounded box").edges, Edges::kBeforeNoun);
  EXPECT_EQ(edgeLeaf("a very rounded box").set, edgeLeaf("a box with very rounded edges").set);
  EXPECT_EQ(edgeLeaf("a slightly softened cube").set, edgeLeaf("a cube with slightly softened edges").set);
  // Not edges: an adjective of a ball (no squareness to round), under "not", or without a noun.
  for (const char* text : {"a rounded ball", "a very rounded ball", "a box that is not rounded", "rounded"})
    for (const QueryCondition& leaf : leavesOf(parse(text).root)) EXPECT_EQ(leaf.edges, Edges::kNone) << text;
  EXPECT_EQ(leavesOf(parse("a rounded ball").root).front().set, v.plainSet(*v.adjective("rounded")));
  // An edge word after an adjective of another descriptor is no edge phrase.
  EXPECT_THROW(parse("a cube with bent edges"), Error);
}

// A cylinder's edges are the rims of its ends (eps1); its round section (eps2 = 1) is no edge.
// Its edge condition is the roundness a cylinder with those edges has, (d + 1) / 2: a plain
// cylinder (eps1 0.1, roundness 0.55) has sharp edges and no rounded ones.
TEST(LinguisticQuery, EdgesOfACylinderAreItsRims) {
  const Vocabulary& v = Vocabulary::builtin();
  const auto edgeSet = [](const std::string& text) {
    for (const QueryCondition& leaf : leavesOf(parse(text).root))
      if (leaf.edges != QueryCondition::Edges::kNone) return leaf.set;
    ADD_FAILURE() << "no edge condition in " << text;
    return FuzzyNumber{};
  };
  const auto half = [](const FuzzyNumber& d) { return add(scale(d, 0.5), FuzzyNumber::crisp(0.5)); };
  EXPECT_EQ(edgeSet("a cylinder with rounded edges"), half(v.edgeSet()));
  EXPECT_EQ(edgeSet("a rounded cylinder"), half(v.edgeSet()));
  EXPECT_EQ(edgeSet("a cylinder with sharp edges"), half(v.sharpEdgeSet()));
  EXPECT_EQ(edgeSet("a cone with soft edges"), half(v.edgeSet()));
  EXPECT_GT(half(v.sharpEdgeSet()).membership(0.55), 0.99);
  EXPECT_EQ(half(v.edgeSet()).membership(0.55), 0.0);
  // A ball has no exponent below 1: both are taken as its edges.
  EXPECT_EQ(edgeSet("a ball with sharp edges"), v.sharpEdgeSet());
}

// Nouns are defaults, not vetoes: the words replace a noun's condition they contradict.
TEST(LinguisticQuery, NounsAreDefaultsTheWordsOverride) {
  const auto descriptorsOfNoun = [](const std::string& text) {
    std::vector<std::string> out;
    for (const QueryCondition& part : parse(text).root.children)
      if (!part.noun.empty())
        for (const QueryCondition& leaf : leavesOf(part)) out.push_back(leaf.descriptor);
    return out;
  };
  // A plate stays flat when it is round; a disc stays flat when square. Their exponent shape is
  // the profile they keep with the words' outline (AFlatNounKeepsItsProfileBesideItsOutlineWord),
  // no longer their own square or round one.
  EXPECT_EQ(descriptorsOfNoun("a round plate"), (std::vector<std::string>{"squariness", "taperness", "elongation"}));
  EXPECT_EQ(descriptorsOfNoun("a square disc"),
            (std::vector<std::string>{"squariness", "roundness", "taperness", "elongation"}));
  for (const QueryCondition& part : parse("a round plate").root.children)
    for (const QueryCondition& leaf : leavesOf(part))
      if (!part.noun.empty() && leaf.descriptor == "squariness") {
        EXPECT_NEAR(leaf.set.core().lo, 0.4, 1e-9);  // a disc's 0.45, not a plate's [0.8, 1]
        EXPECT_NEAR(leaf.set.core().hi, 0.5, 1e-9);
      }
  // And "round" and "square" say a flat noun's outline, its traverse section, before or after it
  // and under "not"; on a ball, a box or no noun they say the whole shape.
  const auto leafDescriptors = [](const std::string& text) {
    std::vector<std::string> out;
    for (const QueryCondition& leaf : leavesOf(parse(text).root))
      if (leaf.noun.empty() && leaf.text.find(':') == std::string::npos) out.push_back(leaf.descriptor);
    return out;
  };
  EXPECT_EQ(leafDescriptors("a round plate"), std::vector<std::string>{"section-roundness"});
  EXPECT_EQ(leafDescriptors("a big round plate"), (std::vector<std::string>{"size", "section-roundness"}));
  EXPECT_EQ(leafDescriptors("plate round big thin"),
            (std::vector<std::string>{"section-roundness", "size", "thickness"}));
  EXPECT_EQ(leafDescriptors("a square disc"), std::vector<std::string>{"section-squariness"});
  EXPECT_EQ(leafDescriptors("a board that is not square"), std::vector<std::string>{"section-squariness"});
  EXPECT_EQ(leafDescriptors("a round ball"), std::vector<std::string>{"roundness"});
  EXPECT_EQ(leafDescriptors("a square box"), std::vector<std::string>{"squariness"});
  EXPECT_EQ(leafDescriptors("round"), std::vector<std::string>{"roundness"});
  EXPECT_EQ(leafDescriptors("a filleted plate"), std::vector<std::string>{"roundness"});
  EXPECT_EQ(leafDescriptors("a plate with a round cross-section"), std::vector<std::string>{"section-roundness"});
  // A box is its exponents' shape: "a round box" keeps it, and so does "a very round box" (a
  // square noun keeps its squareness: "the part of a very round box in a cylinder" is the paper's
  // rounded box).
  EXPECT_EQ(descriptorsOfNoun("a round box"), std::vector<std::string>{"squariness"});
  EXPECT_EQ(descriptorsOfNoun("a very round box"), std::vector<std::string>{"squariness"});
  // Any other noun's exponent shape is a default that an exponent-shape word with a degree of its
  // own replaces: "a very boxy ellipsoid" is very boxy (a part made from those words is), while
  // "a boxy ellipsoid" keeps the ellipsoid's roundness.
  const std::vector<std::string> ellipsoid = descriptorsOfNoun("a big ellipsoid");
  ASSERT_NE(std::find(ellipsoid.begin(), ellipsoid.end(), "roundness"), ellipsoid.end());
  const std::vector<std::string> veryBoxy = descriptorsOfNoun("a very boxy ellipsoid");
  EXPECT_EQ(std::find(veryBoxy.begin(), veryBoxy.end(), "roundness"), veryBoxy.end());
  const std::vector<std::string> boxy = descriptorsOfNoun("a boxy ellipsoid");
  EXPECT_NE(std::find(boxy.begin(), boxy.end(), "roundness"), boxy.end());
  // The same descriptor: replaced only where the words contradict the noun.
  EXPECT_EQ(descriptorsOfNoun("a slightly tapered cone"), (std::vector<std::string>{"squariness", "roundness"}));
  EXPECT_EQ(descriptorsOfNoun("a tapered cylinder"), (std::vector<std::string>{"squariness", "roundness", "taperness"}));
  // A degree of its own (an intensity) on the same descriptor replaces the noun's even where the
  // sets overlap: a part made from "a moderately tapered pyramid" is as tapered as that says.
  EXPECT_EQ(descriptorsOfNoun("a moderately tapered pyramid"), (std::vector<std::string>{"squariness"}));
  EXPECT_EQ(descriptorsOfNoun("a tapered pyramid"), (std::vector<std::string>{"squariness", "taperness"}));
  // A dimension adjective with an intensity sets the proportions; a plain one does not.
  EXPECT_EQ(descriptorsOfNoun("a very thin stick"), (std::vector<std::string>{"roundness", "taperness"}));
  EXPECT_EQ(descriptorsOfNoun("a thin stick"), (std::vector<std::string>{"roundness", "taperness", "elongation"}));
  // Words on the proportions themselves (long, flat) replace the noun's elongation, plain or not:
  // "a long plate" is a plank, long and flat, not a square plate.
  EXPECT_EQ(descriptorsOfNoun("a moderately long stick"), (std::vector<std::string>{"roundness", "taperness"}));
  EXPECT_EQ(descriptorsOfNoun("a long stick"), (std::vector<std::string>{"roundness", "taperness"}));
  EXPECT_EQ(descriptorsOfNoun("a long plate"), (std::vector<std::string>{"squariness", "taperness"}));
  EXPECT_EQ(descriptorsOfNoun("a flat sphere"), std::vector<std::string>{"roundness"});
  // A board is its own noun: square-edged, flat and long; "a long board" agrees with it.
  EXPECT_EQ(descriptorsOfNoun("a bent plank"), (std::vector<std::string>{"squariness", "taperness", "flatness", "slenderness"}));
  EXPECT_EQ(descriptorsOfNoun("a long board"), (std::vector<std::string>{"squariness", "taperness", "flatness", "slenderness"}));
  // Words on two extents set the proportions; one does not.
  EXPECT_EQ(descriptorsOfNoun("a plate 8 long and 1 wide"), (std::vector<std::string>{"squariness", "taperness"}));
  EXPECT_EQ(descriptorsOfNoun("a sphere 2 across"), (std::vector<std::string>{"roundness", "elongation"}));
  // Words on a part's edges say the shape of its exponents: they replace a box's squareness
  // whatever else the box keeps; "rounded" before a noun that is square says its edges too.
  EXPECT_EQ(descriptorsOfNoun("a cube with round edges"), (std::vector<std::string>{"taperness", "elongation"}));
  EXPECT_EQ(descriptorsOfNoun("a box with softened corners"), std::vector<std::string>{});
  EXPECT_EQ(descriptorsOfNoun("a rounded box"), std::vector<std::string>{});
  EXPECT_EQ(descriptorsOfNoun("a box that is rounded"), std::vector<std::string>{});
  EXPECT_EQ(descriptorsOfNoun("a box that is not rounded"), std::vector<std::string>{"squariness"});
  EXPECT_EQ(descriptorsOfNoun("a round box"), std::vector<std::string>{"squariness"});
  // A noun with all its conditions replaced still names itself (printing, explain).
  const LinguisticQuery q = parse("a slightly tapered square cone");
  EXPECT_EQ(q.root.children.at(1).noun, "cone");
}

// Adjectives after the noun read as its clause: "ball small" is "a ball that is small".
// A plain word the noun's kept condition caps ("a tapered cylinder": tapered, and the cylinder's
// "hardly tapered", which meet at most at h = 1/3): both leaves score relative to h, so the most
// tapered cylinder the words allow scores 1, and the order of cylinders by taper is what it was.
TEST(LinguisticQuery, APlainWordCappedByItsNounScoresRelativeToTheirMeeting) {
  const LinguisticQuery q = parse("find a tapered cylinder");
  std::vector<QueryCondition> taper;
  for (const QueryCondition& leaf : leavesOf(q.root))
    if (leaf.descriptor == "taperness") taper.push_back(leaf);
  ASSERT_EQ(taper.size(), 2u);
  const double h = heightOfIntersection(taper[0].set, taper[1].set);
  ASSERT_GT(h, 0.2);
  ASSERT_LT(h, 0.5);
  EXPECT_EQ(taper[0].relativeTo, h);
  EXPECT_EQ(taper[1].relativeTo, h);
  EXPECT_EQ(toJson(q)["condition"]["children"][0]["relative_to"], h);
  const auto cylinder = [&](double t) {
    return scoreDescriptors(q, {{"squariness", FuzzyNumber::crisp(0.45)},
                                {"roundness", FuzzyNumber::crisp(0.55)},
                                {"taperness", FuzzyNumber::crisp(t)}})
        .score;
  };
  double best = 0, bestT = 0;
  for (double t = 0; t <= 1.0; t += 0.001) {
    const double raw = std::min(taper[0].set.membership(t), taper[1].set.membership(t));
    EXPECT_NEAR(cylinder(t), std::min(1.0, raw / h), 1e-9) << t;
    if (cylinder(t) > best) best = cylinder(t), bestT = t;
  }
  EXPECT_NEAR(best, 1.0, 1e-2);
  EXPECT_GT(bestT, 0.3);
  EXPECT_LT(cylinder(0.2), cylinder(1.0 / 3));  // the designers' tapered cylinder before the slightly tapered one
  EXPECT_EQ(cylinder(1.0), 0.0);                // and a cone is no cylinder
  // Where the two meet fully, under "not" or "or", with an intensity (which replaces the noun's
  // condition), or with no noun condition on the descriptor: no rescaling.
  for (const char* text : {"find a long board", "find a cylinder that is not tapered", "find a slightly tapered cylinder",
                           "find a tapered ball", "find a cylinder that is tapered or bent"})
    for (const QueryCondition& leaf : leavesOf(parse(text).root)) EXPECT_EQ(leaf.relativeTo, 1.0) << text;
}

// An exponent word beside a noun's kept exponent shape on another descriptor ("a round box": round,
// and the box's squareness) scores relative to the most the two give together over every pair of
// exponents, as a plain word and its noun's condition on one descriptor do.
TEST(LinguisticQuery, AnExponentWordBesideANounsShapeScoresRelativeToTheirMeeting) {
  const LinguisticQuery q = parse("find a round box");
  std::vector<QueryCondition> leaves = leavesOf(q.root);
  ASSERT_EQ(leaves.size(), 2u);
  const QueryCondition& round = leaves[0].descriptor == "roundness" ? leaves[0] : leaves[1];
  const QueryCondition& box = leaves[0].descriptor == "roundness" ? leaves[1] : leaves[0];
  ASSERT_EQ(box.descriptor, "squariness");
  // Below 1 the two exponent degrees sum to 1 (sq = 1 − e, ro = e), so the meeting is where the
  // box's trap(0.6, 0.8, 1, 1) over 1 − e falls to round's rising set over e.
  double h = 0;
  for (double e = 0.01; e <= 1.0; e += 1e-4)
    h = std::max(h, std::min(round.set.membership(e), box.set.membership(1 - e)));
  EXPECT_NEAR(round.relativeTo, h, 0.01);
  EXPECT_EQ(round.relativeTo, box.relativeTo);
  EXPECT_LT(h, 0.5);
  const auto score = [&](double e) {
    return scoreDescriptors(q, {{"roundness", FuzzyNumber::crisp(e)}, {"squariness", FuzzyNumber::crisp(1 - e)}}).score;
  };
  double best = 0;
  for (double e = 0.01; e <= 1.0; e += 1e-3) {
    EXPECT_NEAR(score(e), std::min(1.0, std::min(round.set.membership(e), box.set.membership(1 - e)) / round.relativeTo),
                1e-9);
    best = std::max(best, score(e));
  }
  EXPECT_EQ(best, 1.0);
  // No shape in common ("a pinched box"), or the noun's shape replaced ("a very boxy ball", "a
  // round plate"): no rescaling.
  for (const char* text : {"find a pinched box", "find a very boxy ball", "find a round plate", "find a rounded box"})
    for (const QueryCondition& leaf : leavesOf(parse(text).root)) EXPECT_EQ(leaf.relativeTo, 1.0) << text;
}

// A flat noun whose outline the words set keeps its profile: "a round plate" is a disc (flat faces,
// sharp rims), not a ball squashed flat, whose outline is as round.
TEST(LinguisticQuery, AFlatNounKeepsItsProfileBesideItsOutlineWord) {
  const auto score = [](const std::string& text, double eps1, double eps2) {
    PlacedSuperquadric p;
    p.params.eps1 = eps1;
    p.params.eps2 = eps2;
    p.params.a1 = 1;
    p.params.a2 = 1;
    p.params.a3 = 0.1;
    std::vector<DescriptorValue> values;
    for (const std::string& d : descriptorNames())
      values.push_back({d, FuzzyNumber::crisp(descriptorDegree(descriptorIndex(d), p))});
    return scoreDescriptors(parse(text), values).score;
  };
  EXPECT_EQ(score("find a round plate", 0.1, 1.0), 1.0);  // a disc
  EXPECT_EQ(score("find a round plate", 1.0, 1.0), 0.0);  // a ball squashed flat
  EXPECT_GE(score("find a square disc", 0.1, 0.01), 0.99);  // a plate with a square outline
  EXPECT_EQ(score("find a square disc", 1.0, 0.01), 0.0);  // a square pillow
  EXPECT_EQ(score("find a plate", 0.1, 0.1), 1.0);
  // The derived conditions are the noun's, named so in explain.
  bool named = false;
  for (const QueryCondition& leaf : leavesOf(parse("find a round plate").root))
    named = named || leaf.text == "plate: squariness";
  EXPECT_TRUE(named);
  // Not for a noun that is not flat, nor without an outline word.
  for (const char* text : {"find a round box", "find a flat plate", "find a plate"}) {
    int squariness = 0;
    for (const QueryCondition& leaf : leavesOf(parse(text).root)) squariness += leaf.descriptor == "squariness";
    EXPECT_LE(squariness, 1) << text;
  }
}

TEST(LinguisticQuery, ConditionsAfterTheNoun) {
  EXPECT_EQ(meaning("ball small"), meaning("a ball that is small"));
  EXPECT_EQ(meaning("cylinder very long and slightly bent"), meaning("a cylinder that is very long and slightly bent"));
  EXPECT_EQ(meaning("cone not sharp"), meaning("a cone that is not sharp"));
  // With measures before them and a "with" clause after them, all hold; they replace the rod's
  // own conditions (two extents its elongation, the round section its roundness) and keep its
  // "hardly tapered".
  EXPECT_EQ(leavesOf(parse("rod 6 long thin with a round cross-section").root).size(), 4u);
  // Not a relation's words: "a sphere above a box" is still a relation.
  EXPECT_EQ(parse("a sphere small above a box").root.kind, Kind::kRelation);
}

// An intensity may follow its adjective, as people say it: a word of the intensities or a phrase
// of intensities.after ("a little", "a lot"), read only there. One that opens the next adjective
// is that adjective's. A condition may follow the noun after a comma.
TEST(LinguisticQuery, IntensitiesAfterTheirAdjective) {
  EXPECT_EQ(meaning("a rod bent slightly"), meaning("a rod that is slightly bent"));
  EXPECT_EQ(meaning("a rod which is bent slightly"), meaning("a rod that is slightly bent"));
  EXPECT_EQ(meaning("a box twisted a little"), meaning("a box that is slightly twisted"));
  EXPECT_EQ(meaning("a box that is twisted a bit"), meaning("a box that is slightly twisted"));
  EXPECT_EQ(meaning("a bar bent a lot"), meaning("a bar that is very bent"));
  EXPECT_EQ(meaning("a cylinder twisted very much"), meaning("a cylinder that is very twisted"));
  EXPECT_EQ(meaning("a rod bent slightly and twisted extremely"), meaning("a rod that is slightly bent and extremely twisted"));
  EXPECT_EQ(meaning("a rod bent slightly tapered"), meaning("a rod that is bent and slightly tapered"));
  EXPECT_EQ(meaning("a box, very twisted"), meaning("a box that is very twisted"));
  EXPECT_EQ(meaning("a cylinder, slightly bent, with a round cross-section"),
            meaning("a cylinder slightly bent with a round cross-section"));
  // The words as said are what explain shows.
  EXPECT_EQ(leavesOf(parse("a rod bent a lot").root).back().text, "bent a lot");
  // Before an adjective "a little" is no intensity: the phrases are read after one only.
  EXPECT_THROW(parse("a little twisted box"), Error);
  // A list of operands keeps its commas.
  EXPECT_EQ(parse("a sphere, small above a box").root.kind, Kind::kRelation);
}

// A width compared along the part is its taper, as "tapered" says it; an intensity before the
// comparative grades it. Where a taper goes adds nothing ("tapering to a point").
TEST(LinguisticQuery, AWidthComparedAlongThePartIsItsTaper) {
  EXPECT_EQ(meaning("a cylinder that gets thinner towards the top"), meaning("a cylinder that is tapered"));
  EXPECT_EQ(meaning("cylinder which get thinner to top"), meaning("a cylinder that is tapered"));
  EXPECT_EQ(meaning("a column getting narrower toward the top"), meaning("a column that is tapered"));
  EXPECT_EQ(meaning("a post wider at the base"), meaning("a post that is tapered"));
  EXPECT_EQ(meaning("a rod much thinner at one end"), meaning("a rod that is very tapered"));
  EXPECT_EQ(meaning("a rod that becomes slightly smaller to its tip"), meaning("a rod that is slightly tapered"));
  EXPECT_EQ(meaning("a cone tapering to a point"), meaning("a cone tapering"));
  EXPECT_EQ(meaning("a pillar narrowing towards the top"), meaning("a pillar narrowing"));
  // A direction phrase is no end of a taper: these stay relations.
  EXPECT_EQ(parse("a cylinder that is tapered to the top of a box").root.kind, Kind::kRelation);
  EXPECT_EQ(parse("a sphere to the top of a cube").root.kind, Kind::kRelation);
  EXPECT_EQ(parse("a box that is spiky to the top right of a sphere").root.kind, Kind::kRelation);
  // A comparative without an end is not read so.
  EXPECT_THROW(parse("a cylinder that gets thinner"), Error);
}

TEST(LinguisticQuery, MeasureErrorsSayWhatIsWrong) {
  EXPECT_NE(errorOf("a box 4 x 2").find("the three sides of a box"), std::string::npos) << errorOf("a box 4 x 2");
  EXPECT_NE(errorOf("a rod -2 long").find("a measure is a positive extent"), std::string::npos);
  EXPECT_NE(errorOf("a ball of radius 1e308").find("too large"), std::string::npos);  // its width overflows
  EXPECT_NE(errorOf("a rod between 4 and 2 long").find("bad measure"), std::string::npos) << errorOf("a rod between 4 and 2 long");
}

TEST(LinguisticQuery, RequestsAndFillersAreSkipped) {
  for (const char* text : {"show me the bent shapes", "please find bent shapes", "I am looking for bent shapes",
                           "i'm looking for bent shapes please", "do you have bent shapes", "find me bent shapes",
                           "are there any bent shapes", "search for bent shapes", "Kindly show bent shapes"})
    EXPECT_EQ(meaning(text), meaning("find bent shapes")) << text;
  // A filler inside the query too.
  EXPECT_EQ(meaning("find very round, please, slightly tapered shapes"),
            meaning("find very round, slightly tapered shapes"));
  // A comma before a filler that does not end the text stays: it joins what follows.
  EXPECT_EQ(meaning("find very round, please slightly tapered shapes"),
            meaning("find very round, slightly tapered shapes"));
}

TEST(LinguisticQuery, IsLinguisticQueryIsWhetherTheTextParses) {
  for (const char* text : {"slightly bent", "show me something twisted", "find a sphere about 3 above a box"})
    EXPECT_TRUE(isLinguisticQuery(text, v())) << text;
  for (const char* text : {"a cube united with a sphere", "find a slightly bnet shape", "find a slightly bent", ""})
    EXPECT_FALSE(isLinguisticQuery(text, v())) << text;
}

TEST(LinguisticQuery, BareDescriptionsAreQueriesAboutAnyShape) {
  EXPECT_EQ(meaning("slightly bent"), meaning("find a slightly bent shape"));
  EXPECT_EQ(parse("slightly bent").subject, "any");
  EXPECT_EQ(meaning("round and slightly tapered"), meaning("find shapes that are round and slightly tapered"));
  EXPECT_EQ(meaning("bendness at least 0.5"), meaning("find shapes with bendness at least 0.5"));
  EXPECT_EQ(meaning("very bent at least 0.7"), meaning("find a very bent shape at least 0.7"));
  // With an article the noun is still expected: the phrase is unfinished.
  const std::string e = errorOf("find a slightly bent");
  EXPECT_NE(e.find("a noun ("), std::string::npos) << e;
}

TEST(LinguisticQuery, PronounsTakeTheirAdjectivesAfterThem) {
  EXPECT_EQ(meaning("show me something twisted"), meaning("find shapes that are twisted"));
  EXPECT_EQ(meaning("anything very round and slightly tapered"),
            meaning("find a very round, slightly tapered shape"));
  EXPECT_EQ(meaning("find something that is bent"), meaning("find shapes that are bent"));
  EXPECT_EQ(parse("something twisted").subject, "any");
}

TEST(LinguisticQuery, SynonymsMeanTheirWords) {
  EXPECT_EQ(meaning("find a bowed bar"), meaning("find a bent rod"));
  EXPECT_EQ(meaning("find a bowed block"), meaning("find a curved box"));
  EXPECT_EQ(meaning("find narrowing bricks"), meaning("find tapered boxes"));
  EXPECT_EQ(meaning("a tapering ball"), meaning("find a tapered sphere"));
}

TEST(LinguisticQuery, SlightlyBentShape) {
  const LinguisticQuery q = parse("find a slightly bent shape");
  EXPECT_EQ(q.subject, "any");
  EXPECT_EQ(q.aggregation, "min");
  EXPECT_EQ(q.atLeast, 0.0);
  expectLeaf(q.root, "bendness", *v().intensity("slightly"), "slightly bent");
}

// queryVerbs and queryArticles are the grammar's words (schema/query_grammar.ebnf), and each one
// opens a query (a verb, with or without "for") or a noun phrase (an article) as the grammar says.
TEST(LinguisticQuery, QueryVerbsAndArticles) {
  EXPECT_EQ(queryVerbs(), (std::vector<std::string>{"find", "show", "search", "get", "list"}));
  EXPECT_EQ(queryArticles(), (std::vector<std::string>{"a", "an", "the", "any", "some", "all"}));
  for (const std::string& verb : queryVerbs())
    for (const std::string& opening : {verb, verb + " for"}) {
      const LinguisticQuery q = parse(opening + " a slightly bent shape");
      expectLeaf(q.root, "bendness", *v().intensity("slightly"), "slightly bent");
    }
  for (const std::string& article : queryArticles()) {
    const LinguisticQuery q = parse("find " + article + " slightly bent shape");
    expectLeaf(q.root, "bendness", *v().intensity("slightly"), "slightly bent");
  }
}

TEST(LinguisticQuery, RelativeClauseWithAnd) {
  const LinguisticQuery q = parse("find shapes that are very round and slightly tapered");
  ASSERT_EQ(q.root.kind, Kind::kAnd);
  EXPECT_EQ(q.root.text, "very round and slightly tapered");
  ASSERT_EQ(q.root.children.size(), 2u);
  expectLeaf(q.root.children[0], "roundness", *v().intensity("very"), "very round");
  expectLeaf(q.root.children[1], "taperness", *v().intensity("slightly"), "slightly tapered");
  // "which is", commas and juxtaposed adjectives mean the same.
  for (const char* same : {"find shapes which are very round, slightly tapered", "find very round slightly tapered shapes",
                           "Find  Shapes That Are VERY round and slightly tapered"}) {
    const LinguisticQuery p = parse(same);
    ASSERT_EQ(p.root.kind, Kind::kAnd) << same;
    EXPECT_EQ(p.root.children[0].set, q.root.children[0].set) << same;
    EXPECT_EQ(p.root.children[1].descriptor, "taperness") << same;
  }
}

TEST(LinguisticQuery, NounConditions) {
  const LinguisticQuery q = parse("find a very bent cylinder");
  ASSERT_EQ(q.root.kind, Kind::kAnd);
  ASSERT_EQ(q.root.children.size(), 2u);
  expectLeaf(q.root.children[0], "bendness", *v().intensity("very"), "very bent");
  const QueryCondition& noun = q.root.children[1];
  EXPECT_EQ(noun.kind, Kind::kAnd);
  EXPECT_EQ(noun.text, "cylinder");
  ASSERT_EQ(noun.children.size(), v().noun("cylinder")->conditions.size());
  for (size_t i = 0; i < noun.children.size(); ++i) {
    EXPECT_EQ(noun.children[i].descriptor, v().noun("cylinder")->conditions[i].descriptor);
    EXPECT_EQ(noun.children[i].text, "cylinder: " + noun.children[i].descriptor);
  }
  // A noun with one condition is that condition; multi-word and plural nouns.
  EXPECT_EQ(parse("find an ellipsoid").root.text, "ellipsoid");
  EXPECT_EQ(parse("find double pyramids").root.text, "double pyramids");
  EXPECT_EQ(parse("find parts").subject, "part");
  const LinguisticQuery any = parse("find shapes");
  EXPECT_EQ(any.root.kind, Kind::kAnd);
  EXPECT_TRUE(any.root.children.empty());
}

// A plain adjective searches with Vocabulary::plainSet (the degree itself, or at least what a
// part made from it has; mirrored for a low pole), marked as a plain ramp; an intensity with its
// set, mirrored for a low pole.
TEST(LinguisticQuery, PlainAndLowPoleAdjectives) {
  const auto plainOf = [](const char* word) { return v().plainSet(*v().adjective(word)); };
  expectLeaf(parse("find a bent shape").root, "bendness", plainOf("bent"), "bent");
  EXPECT_TRUE(parse("find a bent shape").root.plainRamp);
  expectLeaf(parse("find a narrow shape").root, "width", plainOf("narrow"), "narrow");
  EXPECT_NEAR(plainOf("narrow").membership(0.9), 0.1, 1e-12);  // mirrored: 1 − d far from the range
  EXPECT_DOUBLE_EQ(plainOf("narrow").membership(0.0), 1.0);
  expectLeaf(parse("find a flat shape").root, "flatness", plainOf("flat"), "flat");
  expectLeaf(parse("find a long shape").root, "slenderness", plainOf("long"), "long");
  const FuzzyNumber mirroredVery = add(negate(*v().intensity("very")), FuzzyNumber::crisp(1));
  expectLeaf(parse("find a very small part").root, "size", mirroredVery, "very small");
  EXPECT_FALSE(parse("find a very small part").root.plainRamp);
  EXPECT_EQ(mirroredVery.membership(0.1), 1.0);
  // A middle of its descriptor ("truncated") states its own set: no ramp.
  EXPECT_FALSE(parse("find a truncated shape").root.plainRamp);
}

TEST(LinguisticQuery, NotAndOrPrecedence) {
  // not binds tighter than and, and tighter than or.
  const LinguisticQuery q = parse("find shapes that are not twisted and bent or very round");
  ASSERT_EQ(q.root.kind, Kind::kOr);
  ASSERT_EQ(q.root.children.size(), 2u);
  const QueryCondition& both = q.root.children[0];
  ASSERT_EQ(both.kind, Kind::kAnd);
  EXPECT_EQ(both.text, "not twisted and bent");
  ASSERT_EQ(both.children[0].kind, Kind::kNot);
  EXPECT_EQ(both.children[0].text, "not twisted");
  EXPECT_EQ(both.children[0].children[0].descriptor, "twistness");
  EXPECT_EQ(q.root.children[1].text, "very round");
  // Parentheses group.
  const LinguisticQuery p = parse("find shapes that are not (twisted or bent)");
  ASSERT_EQ(p.root.kind, Kind::kNot);
  EXPECT_EQ(p.root.children[0].kind, Kind::kOr);
  EXPECT_EQ(parse("find a not not bent shape").root.children[0].kind, Kind::kNot);
}

TEST(LinguisticQuery, DescriptorDegrees) {
  expectLeaf(parse("find shapes with bendness at least 0.5").root, "bendness", FuzzyNumber::trapezoidal(0.5, 0.5, 1, 1),
             "bendness at least 0.5");
  expectLeaf(parse("find shapes that have twistness at most 0.1").root, "twistness",
             FuzzyNumber::trapezoidal(0, 0, 0.1, 0.1), "twistness at most 0.1");
  // A number phrase restricted to [0, 1]: "about 1" keeps its left half, cut at 1.
  expectLeaf(parse("find shapes which have roundness about 1").root, "roundness",
             FuzzyNumber::fromPoints({{0.9, 0}, {1, 1}}), "roundness about 1");
  expectLeaf(parse("find shapes with size is between 0.2 and 0.4").root, "size", FuzzyNumber::trapezoidal(0.2, 0.2, 0.4, 0.4),
             "size is between 0.2 and 0.4");
  // "at least" after a degree is the threshold; "with score" is never a condition.
  const LinguisticQuery q = parse("find a cylinder with taperness 0.3 at least 0.5");
  EXPECT_DOUBLE_EQ(q.atLeast, 0.5);
  EXPECT_EQ(q.root.children[1].set, FuzzyNumber::crisp(0.3));
  EXPECT_DOUBLE_EQ(parse("find a bent cylinder with score at least 0.25").atLeast, 0.25);
  EXPECT_NE(errorOf("find shapes with bendness at least 1.5").find("degree is in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("find shapes with bendness about 2").find("degree is in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("find shapes with bendness very").find("a degree ("), std::string::npos);
  EXPECT_NE(errorOf("find shapes with bendness at 0.5").find("expected 'least', 'most'"), std::string::npos);
  EXPECT_NE(errorOf("find shapes with bendnes at least 0.5").find("closest known words: bendness"), std::string::npos);
}

TEST(LinguisticQuery, Threshold) {
  EXPECT_DOUBLE_EQ(parse("find a very bent shape at least 0.7").atLeast, 0.7);
  EXPECT_DOUBLE_EQ(parse("find a very bent shape with score at least 0.25").atLeast, 0.25);
  EXPECT_NE(errorOf("find a bent shape at least 1.5").find("[0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("find a bent shape at least").find("a number in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf("find a bent shape with score").find("'at least' NUMBER"), std::string::npos);
}

TEST(LinguisticQuery, Aggregation) {
  EXPECT_EQ(parse("find a very bent cylinder").aggregation, "min");
  EXPECT_EQ(parse("find a very bent cylinder using product").aggregation, "product");
  const LinguisticQuery q = parse("find a very bent cylinder at least 0.3 using mean");
  EXPECT_EQ(q.aggregation, "mean");
  EXPECT_DOUBLE_EQ(q.atLeast, 0.3);
  EXPECT_NE(errorOf("find a very bent cylinder using least").find("an aggregation (mean, min, product)"), std::string::npos);
  EXPECT_NE(errorOf("find a very bent cylinder using max").find("unknown word 'max'"), std::string::npos);
}

TEST(LinguisticQuery, Relations) {
  const LinguisticQuery q = parse("find a cylinder to the left of a cube");
  EXPECT_EQ(q.subject, "shape");
  ASSERT_EQ(q.root.kind, Kind::kRelation);
  EXPECT_EQ(q.root.direction, "left");
  EXPECT_FALSE(q.root.distance.has_value());
  ASSERT_EQ(q.root.children.size(), 2u);
  EXPECT_EQ(q.root.children[0].text, "cylinder");
  EXPECT_EQ(q.root.children[1].text, "cube");
  EXPECT_EQ(q.root.text, "a cylinder to the left of a cube");
  ASSERT_TRUE(q.root.directionSets.has_value());

  const LinguisticQuery d = parse("find a sphere about 3 above a box");
  EXPECT_EQ(d.root.direction, "top");
  ASSERT_TRUE(d.root.distance.has_value());
  EXPECT_EQ(*d.root.distance, FuzzyNumber::triangular(2.7, 3, 3.3));
  EXPECT_EQ(*parse("find a sphere close to the top right of a box").root.distance, *v().distance("close"));
  EXPECT_EQ(parse("find a sphere between 2 and 4 in front of a box").root.direction, "front");
  EXPECT_EQ(parse("find a sphere 2 behind a box").root.distance->core().lo, 2.0);
  EXPECT_EQ(parse("find a cone left front of a very flat plate").root.direction, "left front");
  EXPECT_EQ(parse("find a bent shape below shapes").root.children[1].kind, Kind::kAnd);
}

TEST(LinguisticQuery, DistancesInUnits) {
  EXPECT_EQ(meaning("find a sphere about 3 units above a box"), meaning("find a sphere about 3 above a box"));
  EXPECT_EQ(meaning("a sphere 1 unit to the right of a cube"), meaning("a sphere 1 to the right of a cube"));
  EXPECT_NE(errorOf("a sphere units above a box").find("'units'"), std::string::npos);
}

// Traverse sections (Zhang, Pham & Chen, §1: "very sharp with squarish traverse section"): an
// adjective before a section word describes the section alone, through the vocabulary's section
// descriptors.
TEST(LinguisticQuery, TraverseSections) {
  const LinguisticQuery q = parse("find a very sharp shape with squarish traverse section");
  ASSERT_EQ(q.root.kind, Kind::kAnd);
  ASSERT_EQ(q.root.children.size(), 2u);
  expectLeaf(q.root.children[0], "taperness", *v().intensity("very"), "very sharp");
  expectLeaf(q.root.children[1], "section-squariness", v().plainSet(*v().adjective("squarish")),
             "squarish traverse section");
  // Section words and articles: the same condition.
  const nlohmann::json square = meaning("find shapes with squarish traverse section");
  for (const char* text : {"find shapes with a squarish cross-section", "find shapes with squarish cross section",
                           "find shapes that have a squarish section", "find shapes with squarish traverse sections",
                           "shapes with a squarish traverse-section"})
    EXPECT_EQ(meaning(text), square) << text;
  expectLeaf(parse("a rod with a very round cross-section").root.children[1], "section-roundness",
             *v().intensity("very"), "a very round cross-section");
  expectLeaf(parse("a shape with a circular cross-section").root, "section-roundness",
             v().plainSet(*v().adjective("circular")), "a circular cross-section");
  // After "of", as after "with".
  EXPECT_EQ(meaning("a bar of square section"), meaning("a bar with a square section"));
  EXPECT_EQ(meaning("a rod of a very round cross-section"), meaning("a rod with a very round cross-section"));
  // The seed's own words for Figure 1, a bare description with a "with" clause.
  EXPECT_EQ(meaning("very sharp with squarish traverse section"),
            meaning("find a very sharp shape with squarish traverse section"));
  EXPECT_EQ(meaning("show me something very sharp with a square cross-section"),
            meaning("find a very sharp shape with squarish traverse section"));
  // Without a section word the adjective means the whole shape, as before.
  expectLeaf(parse("a squarish shape").root, "squariness", v().plainSet(*v().adjective("squarish")), "squarish");
  // Designers' shape adjectives: cylindrical and tubular say the section, the others the whole,
  // beside a noun with a shape of its own; beside "shape" those that name a noun's shape are that
  // noun (AnAdjectiveThatNamesAShapeIsItsNoun).
  for (const auto& [word, descriptor] : std::vector<std::pair<const char*, const char*>>{
           {"cylindrical", "section-roundness"}, {"tubular", "section-roundness"}, {"spherical", "roundness"},
           {"conical", "taperness"}, {"pyramidal", "taperness"}, {"cubic", "squariness"},
           {"rectangular", "squariness"}, {"filleted", "roundness"}, {"radiused", "roundness"}}) {
    const QueryCondition beside = parse(std::string("a ") + word + " wedge").root;
    ASSERT_EQ(beside.kind, Kind::kAnd) << word;
    EXPECT_EQ(beside.children[0].descriptor, descriptor) << word;  // its set may meet the wedge's (relative_to)
    EXPECT_EQ(beside.children[0].text, word);
    EXPECT_EQ(beside.children[1].noun, "wedge");
    if (v().adjective(word)->shapeOf.empty())
      expectLeaf(parse(std::string("a ") + word + " shape").root, descriptor, v().plainSet(*v().adjective(word)), word);
    else
      EXPECT_EQ(parse(std::string("a ") + word + " shape").root.noun, v().noun(v().adjective(word)->shapeOf)->word);
  }
  // An adjective that says nothing of a section is an error naming the words and the ones that do.
  const std::string e = errorOf("a shape with a bent cross-section");
  EXPECT_NE(e.find("'a bent cross-section' at character 13"), std::string::npos) << e;
  EXPECT_NE(e.find("square"), std::string::npos) << e;
  EXPECT_NE(e.find("round"), std::string::npos) << e;
  // "a" opens only a section: "a cube with a sphere" stays a noun phrase with its caller's words.
  EXPECT_EQ(parseNounPhraseAt("a cube with a sphere", 0, std::string::npos, v()).end, 6u);
}

TEST(LinguisticQuery, OptionalVerbAndArticles) {
  for (const char* text : {"a slightly bent shape", "show the slightly bent shapes", "search for any slightly bent part",
                           "slightly bent shapes"})
    EXPECT_EQ(parse(text).root.descriptor, "bendness") << text;
}

TEST(LinguisticQuery, ParsedJson) {
  const nlohmann::json j = toJson(parse("find a sphere about 3 above a bent box at least 0.5"));
  EXPECT_EQ(j["subject"], "shape");
  EXPECT_EQ(j["at_least"], 0.5);
  EXPECT_EQ(j["condition"]["kind"], "relation");
  EXPECT_EQ(j["condition"]["direction"], "top");
  EXPECT_EQ(j["condition"]["distance"], nlohmann::json({{"tri", {2.7, 3, 3.3}}}));
  EXPECT_EQ(j["condition"]["children"][1]["children"][0]["set"], toJson(v().plainSet(*v().adjective("bent"))));
}

TEST(LinguisticQuery, UnknownWordsNameTheClosest) {
  const std::string e = errorOf("find a slightly bnet shape");
  EXPECT_NE(e.find("unknown word 'bnet' at character 16"), std::string::npos) << e;
  EXPECT_NE(e.find("bent"), std::string::npos) << e;
  const std::string n = errorOf("find a slightly bent cylindr");
  EXPECT_NE(n.find("'cylindr' at character 21"), std::string::npos) << n;
  EXPECT_NE(n.find("cylinder"), std::string::npos) << n;
  EXPECT_NE(errorOf("find a cube to the lfet of a sphere").find("left"), std::string::npos);
}

// An unknown word's error offers a whole query that reads: the text with the word replaced by a
// near known one.
TEST(LinguisticQuery, UnknownWordsSuggestAQueryThatWorks) {
  std::string e = errorOf("find a slightly bnet shape");
  EXPECT_NE(e.find("unknown word 'bnet' at character 16"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"find a slightly bent shape\"?"), std::string::npos) << e;
  e = errorOf("show me somthing twisted");
  EXPECT_NE(e.find("did you mean \"show me something twisted\"?"), std::string::npos) << e;
  e = errorOf("find shapes that are very rond");
  EXPECT_NE(e.find("did you mean \"find shapes that are very round\"?"), std::string::npos) << e;
  // The suggestion is one that parses.
  const size_t open = e.find("did you mean \"") + 14;
  EXPECT_NO_THROW(parse(e.substr(open, e.find("\"?", open) - open)));
}

TEST(LinguisticQuery, ParseErrorsGivePositionAndExpectedWords) {
  std::string e = errorOf("find a very shape");
  EXPECT_NE(e.find("unexpected 'shape' at character 12"), std::string::npos) << e;
  EXPECT_NE(e.find("expected an adjective (bent, beveled, bevelled"), std::string::npos) << e;
  e = errorOf("find a slightly bent");
  EXPECT_NE(e.find("ends too early (character 20)"), std::string::npos) << e;
  EXPECT_NE(e.find("a noun ("), std::string::npos) << e;
  e = errorOf("find shapes that are");
  EXPECT_NE(e.find("an adjective"), std::string::npos) << e;
  e = errorOf("find shapes that round");
  EXPECT_NE(e.find("expected 'is', 'are'"), std::string::npos) << e;
  e = errorOf("find a cube to the left a sphere");
  EXPECT_NE(e.find("unexpected 'a' at character 24; expected 'of'"), std::string::npos) << e;
  e = errorOf("find a cube sphere");
  EXPECT_NE(e.find("unexpected 'sphere' at character 12"), std::string::npos) << e;
  EXPECT_NE(e.find("the end of the query"), std::string::npos) << e;
  e = errorOf("find shapes that are (round or bent");
  EXPECT_NE(e.find("expected ')'"), std::string::npos) << e;
  e = errorOf("find shapes that are round and");
  EXPECT_NE(e.find("ends too early"), std::string::npos) << e;
  e = errorOf("find a bent shape #");
  EXPECT_NE(e.find("unexpected character '#' at character 18"), std::string::npos) << e;
  e = errorOf("");
  EXPECT_NE(e.find("ends too early"), std::string::npos) << e;
  e = errorOf("find a sphere about above a box");
  EXPECT_NE(e.find("expected a number"), std::string::npos) << e;
}

// The searches read every descriptor condition over its descriptor's degree domain
// (withinDegreeDomains): under "and", "or" and "not" alike, `asked` too; a [0, 1] domain and a set
// whose core lies beyond the end are kept.
TEST(LinguisticQuery, WithinDegreeDomainsReadsEveryConditionOverItsDomain) {
  const LinguisticQuery q = parse("find shapes that are (very square or not extremely large) and slightly bent");
  LinguisticQuery asked = q;
  const LinguisticQuery read = withinDegreeDomains(q);
  int seen = 0;
  const std::function<void(const QueryCondition&, const QueryCondition&)> walk =
      [&](const QueryCondition& before, const QueryCondition& after) {
        ASSERT_EQ(before.kind, after.kind);
        ASSERT_EQ(before.children.size(), after.children.size());
        if (before.kind == Kind::kDescriptor) {
          ++seen;
          const Interval d = degreeDomain(descriptorIndex(before.descriptor));
          EXPECT_EQ(after.set, withinDegrees(before.set, d.lo, d.hi)) << before.text;
          EXPECT_GE(after.set.support().lo, before.descriptor == "bendness" ? 0.0 : d.lo) << before.text;
          EXPECT_LE(after.set.support().hi, d.hi) << before.text;
          EXPECT_EQ(after.text, before.text);
        }
        for (size_t i = 0; i < before.children.size(); ++i) walk(before.children[i], after.children[i]);
      };
  walk(q.root, read.root);
  EXPECT_EQ(seen, 3);
  // very square: trap(0.55, 0.75, 1, 1) cut at 0.99; slightly bent as it is.
  const std::function<const QueryCondition*(const QueryCondition&, const std::string&)> find =
      [&](const QueryCondition& c, const std::string& descriptor) -> const QueryCondition* {
    if (c.kind == Kind::kDescriptor && c.descriptor == descriptor) return &c;
    for (const QueryCondition& child : c.children)
      if (const QueryCondition* f = find(child, descriptor)) return f;
    return nullptr;
  };
  ASSERT_NE(find(read.root, "squariness"), nullptr);
  EXPECT_DOUBLE_EQ(find(read.root, "squariness")->set.support().hi, 0.99);
  EXPECT_DOUBLE_EQ(find(read.root, "squariness")->set.membership(0.99), 1.0);
  EXPECT_EQ(find(read.root, "bendness")->set, find(q.root, "bendness")->set);
  // `asked` (a closest-match query keeps the words' set there) is read over the domain too.
  std::function<void(QueryCondition*)> setAsked = [&](QueryCondition* c) {
    if (c->kind == Kind::kDescriptor) c->asked = c->set;
    for (QueryCondition& child : c->children) setAsked(&child);
  };
  setAsked(&asked.root);
  const LinguisticQuery askedRead = withinDegreeDomains(asked);
  ASSERT_TRUE(find(askedRead.root, "squariness")->asked.has_value());
  EXPECT_DOUBLE_EQ(find(askedRead.root, "squariness")->asked->support().hi, 0.99);
  // The plain ramp of "squarish" (1 only at 1) stays the ramp.
  const LinguisticQuery ramp = parse("find parts with a squarish cross-section");
  EXPECT_EQ(find(withinDegreeDomains(ramp).root, "section-squariness")->set,
            find(ramp.root, "section-squariness")->set);
}

// Deep nesting is a limit, not a stack overflow.
TEST(LinguisticQuery, NestingLimit) {
  auto nested = [](int n) {
    std::string open, close;
    for (int i = 0; i < n; ++i) open += "(", close += ")";
    return "find shapes that are " + open + "bent" + close;
  };
  EXPECT_NO_THROW(parse(nested(60)));
  std::string nots = "find shapes that are";
  for (int i = 0; i < 100000; ++i) nots += " not";
  for (const std::string& text : {nested(100000), nots + " bent"}) {
    try {
      parse(text);
      ADD_FAILURE();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), errc::kLimitExceeded);
      EXPECT_EQ(e.path(), "text");
    }
  }
}

// Every example of schema/query_grammar.ebnf (lines "(* example: ... *)") parses.
TEST(LinguisticQuery, GrammarExamplesParse) {
  int examples = 0;
  for (const std::string& example : testing::grammarExamples("query_grammar.ebnf")) {
    EXPECT_NO_THROW(parse(example)) << example;
    ++examples;
  }
  EXPECT_GE(examples, 15);
}

// NounPhraseReader reads what parseNounPhraseAt reads at every position (ascending, then an
// earlier one again, and a position inside a word), errors included, from one tokenisation.
TEST(NounPhraseReader, GivesWhatParseNounPhraseAtGives) {
  const std::string text = "a very bent cylinder that is long and a box, and (a sphere that is 0.5 round) and a cube";
  auto same = [&](NounPhraseReader& reader, size_t from) {
    std::string expected, got;
    size_t expectedEnd = 0, gotEnd = 0;
    try {
      NounPhraseAt p = parseNounPhraseAt(text, from, std::string::npos, v());
      expected = toJson(p.query).dump();
      expectedEnd = p.end;
    } catch (const Error& e) {
      expected = std::string("error: ") + e.what();
    }
    try {
      NounPhraseAt p = reader.at(from);
      got = toJson(p.query).dump();
      gotEnd = p.end;
    } catch (const Error& e) {
      got = std::string("error: ") + e.what();
    }
    EXPECT_EQ(got, expected) << "from " << from;
    EXPECT_EQ(gotEnd, expectedEnd) << "from " << from;
  };
  NounPhraseReader reader(text, v());
  std::vector<size_t> starts = {0};
  for (size_t i = 1; i < text.size(); ++i)
    if (text[i - 1] == ' ' || text[i - 1] == '(') starts.push_back(i);
  for (size_t from : starts) same(reader, from);
  same(reader, 0);
  same(reader, 3);  // inside "very": read on its own
  NounPhraseReader late(text, v());
  same(late, text.find("a box"));
  same(late, 0);  // before the first call's position: tokenised again
  // A character the linguistic words refuse, after the phrase, is reported as parseNounPhraseAt does.
  const std::string bad = "a cube and a box # x";
  NounPhraseReader badReader(bad, v());
  EXPECT_EQ(test::textErrorOf(bad, [&](const std::string&) { badReader.at(0); }),
            test::textErrorOf(bad, [&](const std::string& t) { parseNounPhraseAt(t, 0, std::string::npos, v()); }));
}

}  // namespace
}  // namespace fsdb
