// Structural query texts (query/structural/csg_query_text.h): both forms, every example of
// schema/csg_query_grammar.ebnf, the leaves as linguistic conditions, and the errors.
#include "query/structural/csg_query_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>


#include "geometry/core/error.h"
#include "query/linguistic/vocabulary.h"
#include "tests/testing/grammar_examples.h"
#include "tests/testing/query_shapes.h"
#include "tests/testing/text_error.h"

namespace fsdb {
namespace {

const Vocabulary& v() { return Vocabulary::builtin(); }
CsgQuery parse(const std::string& text, const ReferenceResolver& resolver = {}) {
  return parseCsgQuery(text, v(), resolver, 1000);
}

std::string shape(const CsgQuery& q) { return testing::csgShape(q); }

std::string errorOf(const std::string& text, const ReferenceResolver& resolver = {}) {
  return test::textErrorOf(text, [&](const std::string& t) { parse(t, resolver); });
}

TEST(CsgQueryText, PhraseOperations) {
  EXPECT_EQ(shape(parse("the union of a very bent cylinder and a very sharp pyramid")),
            "union('a very bent cylinder', 'a very sharp pyramid')");
  EXPECT_EQ(shape(parse("a cube minus a cylinder")), "difference('a cube', 'a cylinder')");
  EXPECT_EQ(shape(parse("the intersection of a sphere and a box")), "intersection('a sphere', 'a box')");
  EXPECT_EQ(shape(parse("a sphere and a box")), "union('a sphere', 'a box')");
  // Lists flatten into one union (associativity, as stored trees do).
  EXPECT_EQ(shape(parse("a sphere, a box and a cylinder")), "union('a sphere', 'a box', 'a cylinder')");
  EXPECT_EQ(shape(parse("find a sphere plus a box plus a cone")), "union('a sphere', 'a box', 'a cone')");
}

// Counts: that many copies of the noun phrase, united; an arrangement that names a direction
// places each copy against the one before it (a row: beside it; a stack: on top of it).
TEST(CsgQueryText, CountsAreCopiesUnited) {
  EXPECT_EQ(shape(parse("two balls")), "union('balls', 'balls')");
  EXPECT_EQ(shape(parse("three slightly bent rods joined together")),
            "union('slightly bent rods', 'slightly bent rods', 'slightly bent rods')");
  EXPECT_EQ(shape(parse("3 spheres in a row")),
            "union('spheres', 'spheres'<side 'spheres'>, 'spheres'<side 'spheres'>)");
  EXPECT_EQ(shape(parse("three balls in line")), "union('balls', 'balls'<side 'balls'>, 'balls'<side 'balls'>)");
  EXPECT_EQ(shape(parse("a pair of cylinders side by side")), "union('cylinders', 'cylinders'<side 'cylinders'>)");
  EXPECT_EQ(shape(parse("two cubes next to each other")), "union('cubes', 'cubes'<side 'cubes'>)");
  EXPECT_EQ(shape(parse("three balls stacked up")), "union('balls', 'balls'<top 'balls'>, 'balls'<top 'balls'>)");
  EXPECT_EQ(shape(parse("two balls touching each other")), "union('balls', 'balls')");
  // The verb itself, as a writer in another language or a relative clause says it.
  for (const char* text : {"two balls that touch each other", "two balls touched each other"})
    EXPECT_EQ(toJson(parse(text)).dump(), toJson(parse("two balls touching each other")).dump()) << text;
  EXPECT_EQ(shape(parse("two ball touch each other")), "union('ball', 'ball')");
  EXPECT_EQ(shape(parse("three balls which are joined in line")),
            "union('balls', 'balls'<side 'balls'>, 'balls'<side 'balls'>)");
  EXPECT_EQ(shape(parse("four cubes lined up")), "union('cubes', 'cubes'<side 'cubes'>, 'cubes'<side 'cubes'>, 'cubes'<side 'cubes'>)");
  // The relation names the copy before it and the words that placed it.
  const CsgQuery row = parse("3 spheres in a row");
  ASSERT_EQ(row.leaves.size(), 3u);
  EXPECT_FALSE(row.leaves[0].relation);
  for (size_t k = 1; k < 3; ++k) {
    ASSERT_TRUE(row.leaves[k].relation) << k;
    EXPECT_EQ(row.leaves[k].relation->text, "in a row");
    EXPECT_EQ(row.leaves[k].relation->direction.word, "side");
  }
  EXPECT_NE(row.leaves[1].relation->to, row.leaves[2].relation->to);
  EXPECT_EQ(shape(parse("a cube minus two spheres")), "difference('a cube', union('spheres', 'spheres'))");
  // Collective nouns: at least two copies, placed as the noun says unless an arrangement does.
  EXPECT_EQ(shape(parse("a stack of spheres")), "union('spheres', 'spheres'<top 'spheres'>)");
  EXPECT_EQ(shape(parse("a stack of three balls")), "union('balls', 'balls'<top 'balls'>, 'balls'<top 'balls'>)");
  EXPECT_EQ(shape(parse("a row of cubes")), "union('cubes', 'cubes'<side 'cubes'>)");
  EXPECT_EQ(shape(parse("an array of 3 cubes")), "union('cubes', 'cubes'<side 'cubes'>, 'cubes'<side 'cubes'>)");
  EXPECT_EQ(shape(parse("a set of two cylinders")), "union('cylinders', 'cylinders')");
  EXPECT_EQ(shape(parse("a pile of two balls side by side")), "union('balls', 'balls'<side 'balls'>)");
  const CsgQuery stack = parse("a stack of three balls");
  ASSERT_TRUE(stack.leaves[1].relation);
  EXPECT_EQ(stack.leaves[1].relation->text, "stack of");
  // A number before units or sides is no count.
  EXPECT_THROW(parse("2 units"), Error);
}

// Ends of a part: the noun phrase united with the part before it (or the object after "of"), with
// no direction (an end lies along that part's long axis, not in a world direction); both ends
// make two copies, as a count does.
TEST(CsgQueryText, PartsAtTheEndsOfAPart) {
  for (const char* text : {"a stick with balls on both ends", "a stick with a ball at each end",
                           "a stick with a ball at either end", "a stick with balls at its ends",
                           "a stick with balls on both the ends", "a stick with a ball on every end"}) {
    const std::string got = shape(parse(text));
    EXPECT_EQ(got.rfind("union('a stick', ", 0), 0u) << text << ": " << got;
    const CsgQuery q = parse(text);
    ASSERT_EQ(q.leaves.size(), 3u) << text;
    for (const CsgQueryLeaf& leaf : q.leaves) EXPECT_FALSE(leaf.relation) << text;
    EXPECT_EQ(q.leaves[1].text, q.leaves[2].text) << text;
  }
  EXPECT_EQ(shape(parse("a plate with a peg at its end")), "union('a plate', 'a peg')");
  EXPECT_EQ(shape(parse("a plate with a peg on the end")), "union('a plate', 'a peg')");
  EXPECT_EQ(shape(parse("a ball at the end of a rod")), "union('a ball', 'a rod')");
  EXPECT_EQ(shape(parse("balls on both ends of a rod")), "union('balls', 'balls', 'a rod')");
  EXPECT_EQ(shape(parse("a rod and a ball at the end of it")), "union('a rod', 'a ball')");
  // A hollowed or drilled part is not copied by halves: one difference, not a whole second copy.
  EXPECT_EQ(shape(parse("a rod with drilled balls on both ends")),
            "union('a rod', difference('balls', 'drilled'))");
  // Other words after "at" and "on" stay relations.
  EXPECT_EQ(shape(parse("a box with a cylinder on its side")), "union('a box', 'a cylinder'<side 'a box'>)");
}

// The phrase form opens with the linguistic grammar's verbs and names operations after its articles.
TEST(CsgQueryText, DesignersPhrasingsOfAUnion) {
  const std::string tree = "union('a very bent cylinder', 'a very sharp pyramid')";
  for (const char* text : {"find a shape which is the union of a very bent cylinder and a very sharp pyramid",
                           "a very bent cylinder united with a very sharp pyramid",
                           "a very bent cylinder combined with a very sharp pyramid",
                           "a very bent cylinder joined with a very sharp pyramid",
                           "a very bent cylinder joined to a very sharp pyramid",
                           "a very bent cylinder together with a very sharp pyramid",
                           "a very bent cylinder along with a very sharp pyramid",
                           "show me shapes made of a very bent cylinder and a very sharp pyramid",
                           "please find something that is the union of a very bent cylinder and a very sharp pyramid",
                           "made of a very bent cylinder and a very sharp pyramid",
                           "I am looking for a part that is made of a very bent cylinder and a very sharp pyramid",
                           "objects composed of a very bent cylinder and a very sharp pyramid"})
    EXPECT_EQ(shape(parse(text)), tree) << text;
  EXPECT_EQ(shape(parse("find shapes made of a cube and a sphere")), "union('a cube', 'a sphere')");
  // Fillers: the comma after one goes with it, a comma before one that ends nothing stays.
  EXPECT_EQ(shape(parse("please, a cube, please a sphere, please")), "union('a cube', 'a sphere')");
  EXPECT_EQ(shape(parse("a cube, please, a sphere")), "union('a cube', 'a sphere')");
  EXPECT_EQ(shape(parse("a shape which is the difference of a cube and a sphere")), "difference('a cube', 'a sphere')");
  // A generic noun that opens a list without a lead-in stays a leaf.
  EXPECT_EQ(shape(parse("a shape and a sphere")), "union('a shape', 'a sphere')");
  EXPECT_EQ(shape(parse("a shape that is bent and a sphere")), "union('a shape that is bent', 'a sphere')");
}

TEST(CsgQueryText, DesignersPhrasingsOfDifferencesAndIntersections) {
  for (const char* text : {"a cube with a sphere cut out", "a cube with a sphere removed", "a cube drilled with a sphere",
                           "a cube drilled through by a sphere", "a cube with a sphere taken out",
                           "a cube minus a sphere", "a cube without a sphere"})
    EXPECT_EQ(shape(parse(text)), "difference('a cube', 'a sphere')") << text;
  // Holes: the shape the hole's word names, a cylinder when none.
  for (const char* text : {"a cube with a cylindrical hole", "a cube with a cylinder-shaped hole", "a cube with a hole",
                           "a cube with a round hole"})
    EXPECT_EQ(shape(parse(text)).rfind("difference('a cube', '", 0), 0u) << text;
  const CsgQuery holed = parse("a cube with a cylindrical hole");
  ASSERT_EQ(holed.leaves.size(), 2u);
  EXPECT_EQ(holed.leaves[1].text, "a cylindrical hole");
  EXPECT_EQ(toJson(*holed.leaves[1].condition), toJson(*parse("a cylinder").leaves[0].condition));
  EXPECT_EQ(shape(parse("a box with a sphere-shaped hole")), "difference('a box', 'a sphere-shaped hole')");
  // A relative clause may say the part has it, and where it is adds nothing.
  for (const char* text : {"a cube which has a hole", "cube which have a hole", "a cube that has a hole in it",
                           "a cube with a hole through the middle", "a cube with a hole in the centre",
                           "a cube that has a cylindrical hole through the center"}) {
    const CsgQuery q = parse(text);
    EXPECT_EQ(shape(q).rfind("difference(", 0), 0u) << text;
    ASSERT_EQ(q.leaves.size(), 2u) << text;
    EXPECT_EQ(toJson(*q.leaves[0].condition), toJson(*parse("a cube").leaves[0].condition)) << text;
    EXPECT_EQ(toJson(*q.leaves[1].condition), toJson(*parse("a cylinder").leaves[0].condition)) << text;
  }
  EXPECT_EQ(shape(parse("a cube with a hole in the middle")), "difference('a cube', 'a hole')");
  // A size before the hole is its width, as an engineer writes it.
  for (const char* text : {"cube with 0.8 hole through center", "a cube with a 0.8 hole", "a cube with a 0.8 unit round hole",
                           "a cube which has a 0.8 hole"}) {
    const CsgQuery q = parse(text);
    EXPECT_EQ(shape(q).rfind("difference(", 0), 0u) << text;
    ASSERT_EQ(q.leaves.size(), 2u) << text;
    EXPECT_EQ(toJson(*q.leaves[1].condition), toJson(*parse("a cylinder 0.8 across").leaves[0].condition)) << text;
  }
  EXPECT_THROW(parse("a cube with a -1 hole"), Error);
  // Hollow: the part minus a part of its own noun, whatever else the words say of the part.
  EXPECT_EQ(shape(parse("a hollow cylinder")), "difference('cylinder', 'hollow')");
  EXPECT_EQ(shape(parse("find a hollow box")), "difference('box', 'hollow')");
  // Annular (ring-shaped): a disc with a hole through it, a washer.
  EXPECT_EQ(shape(parse("an annular disc")), "difference('disc', 'annular')");
  EXPECT_NE(errorOf("an annular shape").find("'annular shape' needs a noun with a shape"), std::string::npos);
  const CsgQuery tube = parse("a hollow slightly bent cylinder");
  ASSERT_EQ(tube.leaves.size(), 2u);
  EXPECT_EQ(tube.leaves[0].text, "slightly bent cylinder");
  EXPECT_EQ(toJson(*tube.leaves[1].condition), toJson(*parse("a cylinder").leaves[0].condition));
  // After the part's adjectives, the same ("a bent hollow tube" as "a hollow bent tube").
  const CsgQuery after = parse("a slightly bent hollow cylinder");
  ASSERT_EQ(after.leaves.size(), 2u);
  EXPECT_EQ(after.leaves[0].text, "slightly bent cylinder");
  EXPECT_EQ(toJson(*after.leaves[0].condition), toJson(*tube.leaves[0].condition));
  EXPECT_EQ(shape(parse("a very big drilled block")), shape(parse("a drilled very big block")));
  EXPECT_EQ(shape(parse("a sphere and a bent hollow tube")), shape(parse("a sphere and a hollow bent tube")));
  // After its noun, ending the noun phrase, hollow too (a non-native order: "tube hollow").
  EXPECT_EQ(shape(parse("tube hollow which is bent")), shape(parse("hollow tube which is bent")));
  EXPECT_EQ(shape(parse("a slightly bent tube hollow")), shape(parse("a hollow slightly bent tube")));
  EXPECT_EQ(shape(parse("a plate drilled with a rod")), "difference('a plate', 'a rod')");
  // The hollowed part may be placed, and be the part another is placed against.
  EXPECT_EQ(shape(parse("a hollow cylinder on top of a box")),
            "union(difference('cylinder'<top 'a box'>, 'hollow'), 'a box')");
  EXPECT_EQ(shape(parse("a box with a hollow ball on top")),
            "union('a box', difference('ball'<top 'a box'>, 'hollow'))");
  // Drilled, bored, pierced, perforated, holed: the part with a hole, as "with a hole" reads.
  for (const char* word : {"drilled", "bored", "pierced", "perforated", "holed"}) {
    const CsgQuery drilled = parse(std::string("a ") + word + " block");
    EXPECT_EQ(shape(drilled), std::string("difference('block', '") + word + "')");
    ASSERT_EQ(drilled.leaves.size(), 2u);
    EXPECT_EQ(toJson(*drilled.leaves[1].condition), toJson(*holed.leaves[1].condition)) << word;
  }
  EXPECT_EQ(shape(parse("a drilled cube on top of a box")),
            "union(difference('cube'<top 'a box'>, 'drilled'), 'a box')");
  EXPECT_EQ(shape(parse("a plate drilled with a rod")), "difference('a plate', 'a rod')");
  // A noun without a shape cannot be hollowed: a 422 that says so.
  EXPECT_NE(errorOf("a hollow shape").find("needs a noun with a shape"), std::string::npos);
  // "with" alone joins a union; the cut applies to all before it.
  EXPECT_EQ(shape(parse("a cube with a sphere")), "union('a cube', 'a sphere')");
  EXPECT_EQ(shape(parse("a cube and a box with a cylinder cut out")),
            "difference(union('a cube', 'a box'), 'a cylinder')");
  // A condition after "with" stays the leaf's own.
  EXPECT_EQ(shape(parse("a box with bendness at least 0.5 minus a cone")),
            "difference('a box with bendness at least 0.5', 'a cone')");
  // The part of X inside Y: their intersection.
  EXPECT_EQ(shape(parse("the part of a sphere inside a cube")), "intersection('a sphere', 'a cube')");
  EXPECT_EQ(shape(parse("find the part of a very round box within a cylinder")),
            "intersection('a very round box', 'a cylinder')");
  EXPECT_EQ(shape(parse("a shape which is the part of a sphere inside a cube")), "intersection('a sphere', 'a cube')");
  EXPECT_NE(errorOf("the part of a sphere and a cube").find("expected 'inside', 'within'"), std::string::npos);
  // Where X and Y overlap, the common part of X and Y: their intersection too.
  for (const char* text : {"where a sphere and a cube overlap", "the part where a sphere and a cube meet",
                           "find the common part of a sphere and a cube", "a shape where a sphere and a cube intersect"})
    EXPECT_EQ(shape(parse(text)), "intersection('a sphere', 'a cube')") << text;
  EXPECT_EQ(shape(parse("the common part of a sphere, a cube and a cone")),
            "intersection('a sphere', 'a cube', 'a cone')");
  EXPECT_NE(errorOf("where a sphere and a cube").find("expected 'overlap'"), std::string::npos);
}

TEST(CsgQueryText, PhraseVerbsAndArticlesAreTheLinguisticOnes) {
  for (const std::string& verb : queryVerbs())
    for (const std::string& opening : {verb, verb + " for"})
      EXPECT_EQ(shape(parse(opening + " a sphere plus a box")), "union('a sphere', 'a box')") << opening;
  for (const std::string& article : queryArticles())
    EXPECT_EQ(shape(parse(article + " union of a sphere and a box")), "union('a sphere', 'a box')") << article;
}

TEST(CsgQueryText, PhraseNestingAndPrecedence) {
  EXPECT_EQ(shape(parse("the union of a cube and the difference of a box and a cylinder")),
            "union('a cube', difference('a box', 'a cylinder'))");
  // Lists bind tighter than minus; intersected with tighter than lists.
  EXPECT_EQ(shape(parse("a cube minus a cylinder and a sphere")),
            "difference('a cube', union('a cylinder', 'a sphere'))");
  EXPECT_EQ(shape(parse("a sphere intersected with a box and a cone")),
            "union(intersection('a sphere', 'a box'), 'a cone')");
  EXPECT_EQ(shape(parse("(a cube plus a sphere) minus a cylinder")),
            "difference(union('a cube', 'a sphere'), 'a cylinder')");
  EXPECT_EQ(shape(parse("a cube minus (a cylinder minus a sphere)")),
            "difference('a cube', difference('a cylinder', 'a sphere'))");
  // A chain of minus keeps the minuend first and the subtrahends after it.
  EXPECT_EQ(shape(parse("a cube minus a cylinder minus a sphere")).rfind("difference(", 0), 0u);
}

TEST(CsgQueryText, LeavesAreNounPhrasesOfTheLinguisticParser) {
  const CsgQuery q = parse("the union of a cylinder that is bent and sharp and a bent and twisted rod");
  EXPECT_EQ(shape(q), "union('a cylinder that is bent and sharp', 'a bent and twisted rod')");
  ASSERT_EQ(q.leaves.size(), 2u);
  for (const CsgQueryLeaf& leaf : q.leaves) {
    ASSERT_TRUE(leaf.condition.has_value());
    EXPECT_EQ(leaf.partId, 0);
  }
  // The leaf's condition is what the linguistic parser makes of the same words.
  EXPECT_EQ(toJson(*q.leaves[1].condition), toJson(parseLinguisticQuery("a bent and twisted rod", v())));
  EXPECT_EQ(q.form, "phrase");
  // "parsed" shows the descriptions where they stand.
  const nlohmann::json parsed = toJson(q);
  EXPECT_EQ(parsed["tree"]["op"], "union");
  EXPECT_EQ(parsed["tree"]["children"][0]["text"], "a cylinder that is bent and sharp");
  EXPECT_EQ(parsed["tree"]["children"][0]["condition"]["kind"], "and");
  EXPECT_EQ(parsed["nodes"], 3);
  EXPECT_EQ(parsed["leaves"], 2);
}

TEST(CsgQueryText, GraphPathsPointIntoTheParsedTree) {
  const CsgQuery q = parse("the union of a cube and the difference of a box and a cylinder");
  const nlohmann::json parsed = toJson(q);
  for (const CsgGraphNode& n : q.graph.nodes) {
    ASSERT_EQ(n.path.rfind("tree", 0), 0u) << n.path;
    if (n.op != CsgGraphOp::Leaf) continue;
    // "tree.children[1].children[0]" → the description at that place.
    nlohmann::json at = parsed["tree"];
    std::string rest = n.path.substr(4);
    while (!rest.empty()) {
      ASSERT_EQ(rest.rfind(".children[", 0), 0u) << n.path;
      const size_t close = rest.find(']');
      at = at["children"][std::stoul(rest.substr(10, close - 10))];
      rest = rest.substr(close + 1);
    }
    EXPECT_EQ(at["text"], q.leaves[n.leaf].text) << n.path;
  }
}

// A resolver that knows a stored part "bolt" (id 7) and a stored shape "pair" (id 9) = union of two bolts.
ReferenceResolver testResolver() {
  return [](const std::string& kind, const nlohmann::json& key) -> std::optional<ResolvedReference> {
    const nlohmann::json bolt = {{"kind", "part"}, {"name", "bolt"}, {"params", {{"a1", 2}, {"a3", 4}}}};
    if (kind == "part" && (key == "bolt" || key == 7)) return ResolvedReference{7, bolt};
    if (kind == "shape" && (key == "pair" || key == 9))
      return ResolvedReference{
          9, {{"kind", "shape"}, {"name", "pair"}, {"tree", {{"op", "intersection"}, {"children", {{{"part", "bolt"}}, {{"part", {{"params", {{"a1", 1}}}}}}}}}}}};
    return std::nullopt;
  };
}

TEST(CsgQueryText, FormulaNamesAreStoredObjectsOrDescriptions) {
  const CsgQuery q = parse("C = \"very bent cylinder\" + bolt - (cube * pair)", testResolver());
  EXPECT_EQ(q.form, "formula");
  EXPECT_EQ(shape(q), "difference(union('very bent cylinder', 'bolt'), intersection('cube', 'bolt', ''))");
  int parts = 0, descriptions = 0;
  for (const CsgQueryLeaf& leaf : q.leaves) {
    if (leaf.condition) ++descriptions;
    else ++parts;
  }
  EXPECT_EQ(descriptions, 2);
  EXPECT_EQ(parts, 3);
  for (const CsgQueryLeaf& leaf : q.leaves) {
    if (leaf.text == "bolt") {
      EXPECT_EQ(leaf.partId, 7);
    }
  }
  // Without a resolver every name is a description.
  EXPECT_EQ(shape(parse("cube + cylinder")), "union('cube', 'cylinder')");
}

// Each stored reference is looked up once per query: the formula asks for every name as a part and
// as a shape, and building the graph asks again; the answers are remembered (rememberingResolver).
TEST(CsgQueryText, FormulaLooksUpEachReferenceOnce) {
  std::map<std::string, int> calls;
  const ReferenceResolver inner = testResolver();
  const ReferenceResolver counting = [&](const std::string& kind, const nlohmann::json& key) {
    ++calls[kind + ' ' + key.dump()];
    return inner(kind, key);
  };
  const CsgQuery q = parse("C = bolt + bolt - (cube * pair)", counting);
  EXPECT_EQ(shape(q), "difference(union('bolt', 'bolt'), intersection('cube', 'bolt', ''))");
  EXPECT_FALSE(calls.empty());
  for (const auto& [what, n] : calls) EXPECT_EQ(n, 1) << what;
}

TEST(CsgQueryText, FormIsChosenByCharacters) {
  EXPECT_TRUE(isCsgFormula("A + B"));
  EXPECT_TRUE(isCsgFormula("A - B"));
  EXPECT_TRUE(isCsgFormula("A -B"));
  EXPECT_TRUE(isCsgFormula("\"bent rod\""));
  EXPECT_TRUE(isCsgFormula("C = A"));
  EXPECT_FALSE(isCsgFormula("a cube-like box minus a sphere"));
  EXPECT_FALSE(isCsgFormula("the union of a sphere and a box"));
  // A sign inside a number is no operator: such a text was sent to the formula parser and refused.
  EXPECT_FALSE(isCsgFormula("a sphere about 2.5e+3 units above a cube"));
  EXPECT_FALSE(isCsgFormula("a sphere about 1E+2 units above a cube"));
  EXPECT_FALSE(isCsgFormula("a sphere between -3 and 2e-1 units above a cube"));
  EXPECT_TRUE(isCsgFormula("part1e+2"));
  EXPECT_TRUE(isCsgFormula("A +B"));
  EXPECT_TRUE(isCsgFormula("2e+3 + B"));
  EXPECT_TRUE(isCsgFormula("(A)+(B)"));
}

TEST(CsgQueryText, RoutingOfQueryTexts) {
  EXPECT_TRUE(isCsgQueryText("the union of a sphere and a box", v()));
  EXPECT_TRUE(isCsgQueryText("a cube minus a cylinder", v()));
  EXPECT_TRUE(isCsgQueryText("cube + cylinder", v()));
  EXPECT_TRUE(isCsgQueryText("a sphere and a box", v()));  // no linguistic query, a CSG list
  EXPECT_FALSE(isCsgQueryText("find a slightly bent shape", v()));
  EXPECT_FALSE(isCsgQueryText("find shapes that are bent and round", v()));
  EXPECT_FALSE(isCsgQueryText("a cube above a sphere", v()));
  EXPECT_FALSE(isCsgQueryText("find a frobnicated shape", v()));  // the linguistic error is the better one
}

// The shape words of holes are the vocabulary's: a user's file adds its own.
TEST(CsgQueryText, HoleWordsAreVocabularyData) {
  auto doc = v().document();
  doc["holes"]["words"]["ball-like"] = "sphere";
  doc["holes"]["plain"] = "cone";
  const Vocabulary custom = Vocabulary::fromJson(doc);
  EXPECT_EQ(testing::csgShape(parseCsgQuery("a cube with a ball-like hole", custom, {}, 100)),
            "difference('a cube', 'a ball-like hole')");
  const CsgQuery plain = parseCsgQuery("a cube with a hole", custom, {}, 100);
  EXPECT_EQ(plain.leaves[1].condition->root.noun, "cone");
  EXPECT_NE(errorOf("a cube with a ball-like hole").find("ball-like"), std::string::npos);
}

// Spatial relations (Zhang, Pham & Chen, §2.2): "Y on top of X" is the union of both with Y placed
// against X; "X and Y to its right" places Y against the operand before it.
TEST(CsgQueryText, SpatialRelations) {
  const std::string onTop = "union('a sphere'<top 'a cylinder'>, 'a cylinder')";
  for (const char* text : {"a sphere on top of a cylinder", "a sphere above a cylinder", "find a sphere over a cylinder",
                           "a cylinder with a sphere on top", "a cylinder with a sphere on top of it",
                           "a cylinder and a sphere above it", "a cylinder and a sphere on its top"}) {
    const std::string got = shape(parse(text));
    // The union is unordered: both orders of the operands are the same graph.
    EXPECT_TRUE(got == onTop || got == "union('a cylinder', 'a sphere'<top 'a cylinder'>)") << text << ": " << got;
  }
  EXPECT_EQ(shape(parse("the union of a cube and a sphere to its right")), "union('a cube', 'a sphere'<right 'a cube'>)");
  EXPECT_EQ(shape(parse("a cube and a sphere about 2 units to its right")),
            "union('a cube', 'a sphere'<right 'a cube' ~2>)");
  EXPECT_EQ(shape(parse("a sphere about 2 units to the right of a cube")),
            "union('a sphere'<right 'a cube' ~2>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere right of a cube")), "union('a sphere'<right 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere to the left of a cube")), "union('a sphere'<left 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere in front of a cube")), "union('a sphere'<front 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere behind a cube")), "union('a sphere'<back 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere below a cube")), "union('a sphere'<bottom 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere 3 units below a cube")), "union('a sphere'<bottom 'a cube' ~3>, 'a cube')");
  // A number with a signed exponent is a number of the phrase, not a formula's operator.
  EXPECT_EQ(shape(parse("a sphere 2.5e+3 units below a cube")), "union('a sphere'<bottom 'a cube' ~2500>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere close to the top right of a cube")),
            "union('a sphere'<top right 'a cube' ~0.5>, 'a cube')");
  EXPECT_EQ(shape(parse("a cube with a sphere on the left side")), "union('a cube', 'a sphere'<left 'a cube'>)");
  // Beyond the paper's directions: a side, any level direction ("more" in the vocabulary).
  EXPECT_EQ(shape(parse("a box with a cylinder on its side")), "union('a box', 'a cylinder'<side 'a box'>)");
  EXPECT_EQ(shape(parse("a sphere beside a cube")), "union('a sphere'<side 'a cube'>, 'a cube')");
  EXPECT_EQ(shape(parse("a sphere next to a cube")), "union('a sphere'<side 'a cube'>, 'a cube')");
  // A chain: each object is the head of what follows it.
  EXPECT_EQ(shape(parse("a cone on top of a cylinder on top of a box")),
            "union('a cone'<top 'a cylinder'>, 'a cylinder'<top 'a box'>, 'a box')");
  // Relations inside operations, and an operation after a relation.
  EXPECT_EQ(shape(parse("a sphere on top of a cube minus a cylinder")),
            "difference(union('a sphere'<top 'a cube'>, 'a cube'), 'a cylinder')");
  EXPECT_EQ(shape(parse("the union of a box, a sphere above it and a cone to its left")),
            "union('a box', 'a sphere'<top 'a box'>, 'a cone'<left 'a sphere'>)");
  // Direction words that are no relation stay what they were.
  EXPECT_EQ(shape(parse("a cube and a sphere")), "union('a cube', 'a sphere')");
}

TEST(CsgQueryText, SpatialRelationsInTheParsedTree) {
  const CsgQuery q = parse("a cube and a sphere about 2 units to its right");
  const nlohmann::json parsed = toJson(q);
  const nlohmann::json& leaf = parsed["tree"]["children"][1];
  EXPECT_EQ(leaf["text"], "a sphere");
  EXPECT_EQ(leaf["relation"]["text"], "about 2 units to its right");
  EXPECT_EQ(leaf["relation"]["direction"], "right");
  EXPECT_EQ(leaf["relation"]["to"], "tree.children[0]");
  EXPECT_EQ(leaf["relation"]["distance"], nlohmann::json({{"tri", {1.8, 2, 2.2}}}));
  EXPECT_FALSE(parsed["tree"]["children"][0].contains("relation"));
}

TEST(CsgQueryText, SpatialRelationErrorsNameTheWords) {
  const std::string first = errorOf("a sphere to its right");
  EXPECT_NE(first.find("'to its right' at character 9"), std::string::npos) << first;
  EXPECT_NE(first.find("none comes before it"), std::string::npos) << first;
  const std::string composite = errorOf("a sphere on top of the union of a cube and a box");
  EXPECT_NE(composite.find("'on top of' at character 9"), std::string::npos) << composite;
  EXPECT_NE(composite.find("one part"), std::string::npos) << composite;
  const std::string afterOperation = errorOf("(a cube minus a box) and a sphere to its right");
  EXPECT_NE(afterOperation.find("none comes before it"), std::string::npos) << afterOperation;
}

TEST(CsgQueryText, ErrorsGivePositionsAndExpectedWords) {
  EXPECT_NE(errorOf("the union of a cube").find("the query ends too early"), std::string::npos);
  EXPECT_NE(errorOf("the union of a cube").find("'and'"), std::string::npos);
  const std::string e = errorOf("a cube minus a frobnicated sphere");
  EXPECT_NE(e.find("unknown word 'frobnicated' at character 15"), std::string::npos) << e;
  const std::string d = errorOf("the difference of a cube or a sphere");
  EXPECT_NE(d.find("character"), std::string::npos) << d;
  EXPECT_NE(errorOf("(a cube minus a sphere").find("')'"), std::string::npos);
  EXPECT_NE(errorOf("a cube minus").find("noun phrase"), std::string::npos);
  // Formula: csg_text's column message, or the description's own error at its place in the text.
  EXPECT_NE(errorOf("cube + \"very frobnicated rod\"").find("unknown word 'frobnicated' at character 13"), std::string::npos);
  EXPECT_NE(errorOf("\"a cube above a sphere\" + rod").find("is no stored part or shape"), std::string::npos);
  try {
    parse("cube + * rod");
    ADD_FAILURE();
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("column 8"), std::string::npos) << err.what();
    EXPECT_EQ(err.path(), "text");
  }
}

TEST(CsgQueryText, DeepNestingIsALimit) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "(";
  text += "a cube";
  for (int i = 0; i < 100; ++i) text += ")";
  try {
    parse(text);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kLimitExceeded);
  }
}

TEST(CsgQueryText, TooManyNodesIsALimit) {
  std::string text = "a cube";
  for (int i = 0; i < 20; ++i) text += " and a sphere";
  try {
    parseCsgQuery(text, v(), {}, 10);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), errc::kLimitExceeded);
  }
}

TEST(CsgQueryText, TreeDocuments) {
  const nlohmann::json tree = {{"op", "difference"},
                               {"children", {{{"part", "bolt"}}, {{"part", {{"params", {{"a1", 1}}}}}}}}};
  const CsgQuery q = csgQueryFromDocument(tree, 100, testResolver());
  EXPECT_EQ(q.form, "tree");
  EXPECT_EQ(shape(q), "difference('bolt', '')");
  EXPECT_FALSE(q.leaves[0].condition.has_value());
  EXPECT_EQ(q.graph.nodes[q.graph.root].path, "tree");
  EXPECT_EQ(q.tree, tree);
  const CsgQuery whole = csgQueryFromDocument({{"kind", "shape"}, {"name", "x"}, {"tree", tree}}, 100, testResolver());
  EXPECT_EQ(shape(whole), shape(q));
  try {
    csgQueryFromDocument(
        {{"op", "union"}, {"children", {{{"part", "bolt"}}, {{"part", {{"params", {{"a1", -1}}}}}}}}}, 100,
        testResolver());
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.path().rfind("tree.children[1].part", 0), 0u) << e.path();
  }
}

// Every example of schema/csg_query_grammar.ebnf parses, and `fsdb query` and POST /query send it
// to the structural search, except a relation between two noun phrases: that is a linguistic
// query as well (schema/query_grammar.ebnf), and the one search box reads it as one.
TEST(CsgQueryText, GrammarExamplesParse) {
  const std::vector<std::string> linguistic = {"a sphere on top of a cylinder",
                                               "a sphere about 3 units to the right of a cube",
                                               "a sphere close to the top right of a cube",
                                               "a sphere beside a cube"};
  int examples = 0;
  for (const std::string& example : testing::grammarExamples("csg_query_grammar.ebnf")) {
    EXPECT_NO_THROW(parse(example)) << example;
    const bool either = std::find(linguistic.begin(), linguistic.end(), example) != linguistic.end();
    EXPECT_EQ(isCsgQueryText(example, v()), !either) << example;
    EXPECT_EQ(isLinguisticQuery(example, v()), either) << example;
    ++examples;
  }
  EXPECT_GE(examples, 15);
}

}  // namespace
}  // namespace fsdb
