// Closest-match queries (query/linguistic/closest_match.h): widened sets by the extension
// principle, negations left as asked, relations scored without their placement, and explain
// giving each condition's score as asked beside its closeness.
#include "query/linguistic/closest_match.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/document/part_json.h"
#include "query/document/shape_json.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

LinguisticQuery parse(const std::string& text) { return parseLinguisticQuery(text, Vocabulary::builtin()); }

// The first descriptor condition of a tree, pre-order.
const QueryCondition* firstDescriptor(const QueryCondition& c) {
  if (c.kind == QueryCondition::Kind::kDescriptor) return &c;
  for (const QueryCondition& child : c.children)
    if (const QueryCondition* d = firstDescriptor(child)) return d;
  return nullptr;
}

FuzzyPart partOf(const nlohmann::json& params) { return parsePart({{"params", params}}, ""); }

std::vector<ShapeComponent> componentsOf(const nlohmann::json& tree) {
  return shapeComponents(*parseShapeField({{"kind", "shape"}, {"tree", tree}}, "shape", 100).tree);
}

nlohmann::json leaf(const char* noun, double x, double y, double z) {
  return {{"part", {{"params", Vocabulary::builtin().noun(noun)->params}}}, {"transform", {{"translate", {x, y, z}}}}};
}

// Every α-cut grows by w·(1 − α) on each side: the support by w, the core not at all.
TEST(ClosestMatch, WideningAddsATriangleOfHalfWidthW) {
  const LinguisticQuery q = parse("a part about 10 long");
  const QueryCondition* asked = firstDescriptor(q.root);
  ASSERT_NE(asked, nullptr);
  const LinguisticQuery relaxed = closestMatchQuery(q, 0.25);
  const QueryCondition* widened = firstDescriptor(relaxed.root);
  ASSERT_NE(widened, nullptr);
  ASSERT_TRUE(widened->asked.has_value());
  EXPECT_EQ(*widened->asked, asked->set);
  for (double alpha : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const Interval a = asked->set.alphaCut(alpha), w = widened->set.alphaCut(alpha);
    EXPECT_NEAR(w.lo, a.lo - 0.25 * (1 - alpha), 1e-12) << alpha;
    EXPECT_NEAR(w.hi, a.hi + 0.25 * (1 - alpha), 1e-12) << alpha;
  }
  // Widening twice starts again from the set asked, and 0 widens nothing.
  const LinguisticQuery twice = closestMatchQuery(relaxed, 0.5);
  const QueryCondition* again = firstDescriptor(twice.root);
  EXPECT_NEAR(again->set.support().lo, asked->set.support().lo - 0.5, 1e-12);
  const LinguisticQuery same = closestMatchQuery(q, 0.0);
  EXPECT_EQ(firstDescriptor(same.root)->set, asked->set);
  EXPECT_FALSE(firstDescriptor(same.root)->asked.has_value());
  EXPECT_EQ(relaxed.aggregation, q.aggregation);
  EXPECT_EQ(relaxed.subject, q.subject);
  for (double bad : {-0.1, std::nan("")}) {
    try {
      closestMatchQuery(q, bad);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.path(), "widen_by");
    }
  }
}

// A part too short for "about 10 long" scores 0 as asked and above 0 once widened enough, the
// longer part closer; explain keeps the score as asked beside the closeness.
TEST(ClosestMatch, NearerPartsScoreHigherAndExplainSaysWhatFailed) {
  const LinguisticQuery q = parse("a part about 10 long");
  const auto near = describePart(partOf({{"a1", 1}, {"a2", 1}, {"a3", 3}}));  // 6 long
  const auto far = describePart(partOf({{"a1", 1}, {"a2", 1}, {"a3", 1}}));   // 2 long
  EXPECT_EQ(scoreDescriptors(q, near).score, 0.0);
  EXPECT_EQ(scoreDescriptors(q, far).score, 0.0);
  const LinguisticQuery relaxed = closestMatchQuery(q, 0.5);
  const QueryScore n = scoreDescriptors(relaxed, near), f = scoreDescriptors(relaxed, far);
  EXPECT_GT(n.score, f.score);
  EXPECT_GT(f.score, 0.0);
  ASSERT_EQ(n.explain.size(), 1u);
  EXPECT_EQ(n.explain[0].score, 0.0);  // as asked
  ASSERT_TRUE(n.explain[0].closeness.has_value());
  EXPECT_DOUBLE_EQ(*n.explain[0].closeness, n.score);
  const nlohmann::json j = explainJson(n);
  EXPECT_EQ(j[0]["score"], 0.0);
  EXPECT_DOUBLE_EQ(j[0]["closeness"].get<double>(), n.score);
  // The text's own query explains no closeness.
  EXPECT_EQ(explainJson(scoreDescriptors(q, near))[0].count("closeness"), 0u);
}

// "not" is left as asked: widening under it would make the negation stricter.
TEST(ClosestMatch, NegationsStayAsAsked) {
  const LinguisticQuery q = parse("a shape that is not bent");
  const LinguisticQuery relaxed = closestMatchQuery(q, 1.0);
  const QueryCondition* d = firstDescriptor(relaxed.root);
  ASSERT_NE(d, nullptr);
  EXPECT_FALSE(d->asked.has_value());
  EXPECT_EQ(d->set, firstDescriptor(q.root)->set);
}

// A relation whose placement no pair has: relaxed, the shape with both noun phrases scores by
// them, and explain gives the placement's own score (0) beside the closeness.
TEST(ClosestMatch, RelationsScoreTheirNounPhrasesWhereverTheyStand) {
  const LinguisticQuery q = parse("a cone on a box");  // the search box reads "resting" so
  ASSERT_EQ(q.root.kind, QueryCondition::Kind::kRelation);
  const auto beside = componentsOf({{"op", "union"}, {"children", {leaf("box", 0, 0, 0), leaf("cone", 5, 0, 0)}}});
  const auto balls = componentsOf({{"op", "union"}, {"children", {leaf("sphere", 0, 0, 0), leaf("sphere", 5, 0, 0)}}});
  EXPECT_EQ(scoreShape(q, beside).score, 0.0);
  const LinguisticQuery relaxed = closestMatchQuery(q, 0.0);
  EXPECT_TRUE(relaxed.closestMatch);
  const QueryScore s = scoreShape(relaxed, beside);
  EXPECT_DOUBLE_EQ(s.score, 1.0);
  ASSERT_FALSE(s.explain.empty());
  EXPECT_EQ(s.explain[0].text, q.root.text);
  EXPECT_EQ(s.explain[0].score, 0.0);
  ASSERT_TRUE(s.explain[0].closeness.has_value());
  EXPECT_DOUBLE_EQ(*s.explain[0].closeness, 1.0);
  EXPECT_EQ(s.explain[0].component, "tree.children[1], tree.children[0]");
  EXPECT_LT(scoreShape(relaxed, balls).score, 1.0);
  // A cone on top of a box (Y is up) meets the words; relaxed, its placement is explained as met.
  const auto onTop = componentsOf({{"op", "union"}, {"children", {leaf("box", 0, 0, 0), leaf("cone", 0, 3, 0)}}});
  const double asked = scoreShape(q, onTop).score;
  EXPECT_DOUBLE_EQ(asked, 1.0);
  const QueryScore t = scoreShape(relaxed, onTop);
  EXPECT_DOUBLE_EQ(t.score, 1.0);
  EXPECT_DOUBLE_EQ(t.explain[0].score, asked);
}

}  // namespace
}  // namespace fsdb
