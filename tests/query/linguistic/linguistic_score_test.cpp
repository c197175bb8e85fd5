// Scores of linguistic queries on a catalogue with known parameters: rankings follow the words.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_similarity.h"
#include "query/document/part_from_words.h"
#include "query/document/part_json.h"
#include "query/document/shape_json.h"
#include "query/linguistic/linguistic_query.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Item {
  std::string name;
  FuzzyPart part;
};

FuzzyPart part(const nlohmann::json& params, const nlohmann::json& transform = nullptr) {
  nlohmann::json doc = {{"params", params}};
  if (!transform.is_null()) doc["transform"] = transform;
  return parsePart(doc, "");
}

// The names of the items ranked by score (descending, ties by catalogue order), with scores.
std::vector<std::pair<std::string, double>> rank(const std::string& text, const std::vector<Item>& catalogue) {
  const LinguisticQuery q = parseLinguisticQuery(text, Vocabulary::builtin());
  std::vector<std::pair<std::string, double>> out;
  for (const Item& item : catalogue) out.emplace_back(item.name, scoreDescriptors(q, describePart(item.part)).score);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

std::vector<std::string> names(const std::vector<std::pair<std::string, double>>& ranked) {
  std::vector<std::string> n;
  for (const auto& r : ranked) n.push_back(r.first);
  return n;
}

// C = a1·a3 = 2; bendness = |kv|·2C/π.
std::vector<Item> bentCatalogue() {
  auto withBend = [](double bendness) { return part({{"a1", 1}, {"a3", 2}, {"kv", bendness * kPi / 4}}); };
  return {{"straight", withBend(0)}, {"very bent", withBend(0.85)}, {"slightly bent", withBend(0.15)},
          {"moderately bent", withBend(0.5)}};
}

// A plain "bent" ranks by degree up to what a part made "bent" has (the created range's core,
// moderately: 0.45), and scores everything bent at least that much 1 (Vocabulary::plainSet).
TEST(LinguisticScore, BentRanksByDegree) {
  const auto ranked = rank("find a bent shape", bentCatalogue());
  EXPECT_EQ(names(ranked), (std::vector<std::string>{"very bent", "moderately bent", "slightly bent", "straight"}));
  EXPECT_DOUBLE_EQ(ranked[0].second, 1.0);  // 0.85: past the core's start
  EXPECT_DOUBLE_EQ(ranked[1].second, 1.0);  // 0.5: in the core (a tie, kept in catalogue order)
  EXPECT_NEAR(ranked[2].second, 0.15, 1e-12);  // crisp: S = μ(d) = d below the created range
  EXPECT_DOUBLE_EQ(ranked[3].second, 0.0);
  EXPECT_EQ(rank("find a very bent shape", bentCatalogue())[0].first, "very bent");
  EXPECT_EQ(rank("find a slightly bent shape", bentCatalogue())[0].first, "slightly bent");
  EXPECT_DOUBLE_EQ(rank("find a slightly bent shape", bentCatalogue())[0].second, 1.0);
  EXPECT_EQ(rank("find a moderately bent shape", bentCatalogue())[0].first, "moderately bent");
  // Straight (the low pole) reverses the order; "not bent" too.
  EXPECT_EQ(names(rank("find a straight shape", bentCatalogue())),
            (std::vector<std::string>{"straight", "slightly bent", "moderately bent", "very bent"}));
  // "not bent": 1 − the plain score; the moderately and very bent parts both score 0 (a tie, in
  // catalogue order).
  const auto notBent = rank("find shapes that are not bent", bentCatalogue());
  EXPECT_EQ(names(notBent), (std::vector<std::string>{"straight", "slightly bent", "very bent", "moderately bent"}));
  EXPECT_NEAR(notBent[1].second, 0.85, 1e-12);
  EXPECT_DOUBLE_EQ(notBent[2].second, 0.0);
  EXPECT_DOUBLE_EQ(notBent[3].second, 0.0);
  // Nothing satisfies it: every score 0, no error.
  for (const auto& r : rank("find an extremely bent shape at least 0.5", {bentCatalogue()[0]})) EXPECT_EQ(r.second, 0.0);
}

TEST(LinguisticScore, DescriptorDegrees) {
  const auto ranked = rank("find shapes with bendness at least 0.5", bentCatalogue());
  EXPECT_EQ(names(ranked), (std::vector<std::string>{"very bent", "moderately bent", "straight", "slightly bent"}));
  EXPECT_DOUBLE_EQ(ranked[1].second, 1.0);
  EXPECT_DOUBLE_EQ(ranked[2].second, 0.0);
  EXPECT_EQ(rank("find shapes with bendness about 0.15", bentCatalogue())[0].first, "slightly bent");
}

TEST(LinguisticScore, VeryRoundPicksExponentsNearOne) {
  std::vector<Item> catalogue;
  for (double e : {0.1, 0.5, 1.6, 0.7, 1.0, 2.5})
    catalogue.push_back({"eps " + std::to_string(e), part({{"a1", 1}, {"eps1", e}, {"eps2", e}})});
  const auto ranked = rank("find a very round shape", catalogue);
  EXPECT_EQ(ranked[0].first, "eps " + std::to_string(1.0));
  EXPECT_EQ(ranked[1].first, "eps " + std::to_string(0.7));
  EXPECT_DOUBLE_EQ(ranked[0].second, 1.0);
  EXPECT_NEAR(ranked[1].second, 0.75, 1e-12);
  const auto round = rank("find a round shape", catalogue);
  EXPECT_EQ(names(round)[0], "eps " + std::to_string(1.0));
  EXPECT_EQ(names(round)[1], "eps " + std::to_string(0.7));
  EXPECT_EQ(names(round)[5], "eps " + std::to_string(2.5));
  EXPECT_EQ(rank("find a square shape", catalogue)[0].first, "eps " + std::to_string(0.1));
}

TEST(LinguisticScore, ExtremelyTwistedPicksTheMostTwisted) {
  std::vector<Item> catalogue;
  for (double t : {0.0, 0.5, 3.0, 1.5, 2.5})
    catalogue.push_back({"t " + std::to_string(t), part({{"a1", 1}, {"t", t}})});
  const auto ranked = rank("find an extremely twisted shape", catalogue);
  EXPECT_EQ(ranked[0].first, "t " + std::to_string(3.0));
  EXPECT_GT(ranked[0].second, ranked[1].second);
  // Plain "twisted": twistness |t|/π ranks by degree below the created range's core (0.45) and
  // scores 1 from there on: t = 1.5, 2.5 and 3 tie (in catalogue order) above 0.5 and 0.
  const auto twisted = rank("find a twisted shape", catalogue);
  EXPECT_EQ(names(twisted),
            (std::vector<std::string>{"t " + std::to_string(3.0), "t " + std::to_string(1.5), "t " + std::to_string(2.5),
                                      "t " + std::to_string(0.5), "t " + std::to_string(0.0)}));
  EXPECT_DOUBLE_EQ(twisted[2].second, 1.0);
  EXPECT_NEAR(twisted[3].second, 0.5 / kPi, 1e-12);
  EXPECT_EQ(rank("find a very twisted shape", catalogue)[0].first, "t " + std::to_string(3.0));
}

// Fuzzy parameters give fuzzy descriptor values, scored by S (docs/api.md §5).
TEST(LinguisticScore, FuzzyPartsScoreBySimilarity) {
  // kv around bendness 0.15 (slightly): tri over [0.1, 0.15, 0.2] in degree.
  const FuzzyPart slightly = part({{"a1", 1}, {"a3", 2}, {"kv", {{"tri", {0.1 * kPi / 4, 0.15 * kPi / 4, 0.2 * kPi / 4}}}}});
  const auto values = describePart(slightly);
  const FuzzyNumber& bend = values[descriptorIndex("bendness")].value;
  EXPECT_NEAR(bend.support().lo, 0.1, 1e-12);
  EXPECT_NEAR(bend.core().lo, 0.15, 1e-12);
  const LinguisticQuery q = parseLinguisticQuery("find a slightly bent shape", Vocabulary::builtin());
  const double s = scoreDescriptors(q, values).score;
  EXPECT_NEAR(s, similarity(bend, q.root.set), 1e-15);
  EXPECT_GT(s, 0.0);
  EXPECT_LT(s, 1.0);  // the area rule: a narrow datum inside a wide condition
  EXPECT_DOUBLE_EQ(scoreDescriptors(parseLinguisticQuery("find a very bent shape", Vocabulary::builtin()), values).score, 0.0);
}

// Coverage breaks ties of the score: of two parts that satisfy the words fully, the one whose
// value is the words' set itself spans all of it (1), a crisp one nothing (0). Only what the
// words say of the part counts: not a noun's defaults, nothing under "not".
TEST(LinguisticScore, CoverageIsHowMuchOfTheSaidSetsTheValuesSpan) {
  const Vocabulary& v = Vocabulary::builtin();
  const LinguisticQuery q = parseLinguisticQuery("a slightly bent cylinder", v);
  ASSERT_TRUE(saysVagueness(q.root));
  const FuzzyPart made = partFromWords("a slightly bent cylinder", v);
  ASSERT_FALSE(made.kv.isCrisp());
  // A crisp cylinder bent at the middle of the set's core: also a full match.
  const FuzzyNumber& asked = [&]() -> const FuzzyNumber& {
    for (const QueryCondition& c : q.root.children)
      if (c.descriptor == "bendness") return c.set;
    return q.root.set;
  }();
  ASSERT_GT(asked.cardinality(), 0);
  FuzzyPart crisp = made;
  const double middle = 0.5 * (asked.core().lo + asked.core().hi);
  crisp.kv = FuzzyNumber::crisp(middle * kPi / (2 * crisp.a1.core().lo * crisp.a3.core().lo));  // bendness = kv·2C/π, C = a1·a3
  const QueryScore fuzzy = scoreDescriptors(q, describePart(made)), sharp = scoreDescriptors(q, describePart(crisp));
  EXPECT_GE(fuzzy.score, 0.999);
  EXPECT_EQ(sharp.score, 1);
  EXPECT_GE(fuzzy.coverage, 0.999);  // the part's bend is the words' set (sampled every 1/16)
  EXPECT_EQ(sharp.coverage, 0);
  // The cylinder's own conditions (round, straight sides) are crisp in both and count for neither;
  // the bend alone decides: the made part's coverage is its bend's.
  const auto values = describePart(made);
  EXPECT_DOUBLE_EQ(fuzzy.coverage, coverage(values[descriptorIndex("bendness")].value, asked));
  // A noun alone, or only "not": nothing said of the part's degrees, coverage 0 for every part.
  for (const char* text : {"a cylinder", "a cylinder that is not bent", "find a shape that is not twisted"}) {
    const LinguisticQuery nothing = parseLinguisticQuery(text, v);
    EXPECT_FALSE(saysVagueness(nothing.root)) << text;
    EXPECT_EQ(scoreDescriptors(nothing, values).coverage, 0) << text;
  }
  // "or" takes the larger coverage, "and" the smaller.
  const auto cov = [&](const char* text) { return scoreDescriptors(parseLinguisticQuery(text, v), values).coverage; };
  EXPECT_GE(cov("find a shape that is slightly bent or very twisted"), 0.999);
  EXPECT_EQ(cov("find a shape that is slightly bent and very twisted"), 0);
}

// A part made from words takes the words' set through its parameters; its descriptor value comes
// back with other breakpoints, equal but for rounding. It scores exactly 1, as a crisp value in
// the set's core does, so the two tie and coverage decides (it scored 0.9999999999999998, and the
// crisp part came first).
TEST(LinguisticScore, APartMadeFromWordsScoresExactlyOneForThem) {
  const Vocabulary& v = Vocabulary::builtin();
  for (const char* text : {"a moderately huge bar", "a slightly bent cylinder", "a very twisted box"}) {
    const QueryScore s = scoreDescriptors(parseLinguisticQuery(text, v), describePart(partFromWords(text, v)));
    EXPECT_EQ(s.score, 1.0) << text;
    EXPECT_EQ(s.coverage, 1.0) << text;
  }
}

TEST(LinguisticScore, AndOrNotAggregationAndExplain) {
  const FuzzyPart p = part({{"a1", 1}, {"eps1", 0.7}, {"eps2", 0.7}, {"kx", -0.2}, {"ky", -0.2}});  // roundness 0.7, taper 0.2
  const auto values = describePart(p);
  LinguisticQuery q = parseLinguisticQuery("find shapes that are very round and slightly tapered", Vocabulary::builtin());
  const double veryRound = (0.7 - 0.55) / 0.2, slightlyTapered = 1.0;
  QueryScore s = scoreDescriptors(q, values);
  EXPECT_NEAR(s.score, std::min(veryRound, slightlyTapered), 1e-12);
  ASSERT_EQ(s.explain.size(), 3u);
  EXPECT_EQ(s.explain[0].text, "very round and slightly tapered");
  EXPECT_EQ(s.explain[1].text, "very round");
  EXPECT_NEAR(s.explain[1].score, veryRound, 1e-12);
  EXPECT_EQ(s.explain[2].text, "slightly tapered");
  EXPECT_NEAR(s.explain[2].score, 1.0, 1e-12);
  q.aggregation = "product";
  EXPECT_NEAR(scoreDescriptors(q, values).score, veryRound * slightlyTapered, 1e-12);
  q.aggregation = "mean";
  EXPECT_NEAR(scoreDescriptors(q, values).score, (veryRound + slightlyTapered) / 2, 1e-12);
  q.aggregation = "max";
  EXPECT_THROW(scoreDescriptors(q, values), Error);

  const Vocabulary& v = Vocabulary::builtin();
  EXPECT_NEAR(scoreDescriptors(parseLinguisticQuery("find shapes that are very round or twisted", v), values).score, veryRound,
              1e-12);
  EXPECT_NEAR(scoreDescriptors(parseLinguisticQuery("find shapes that are not very round", v), values).score, 1 - veryRound,
              1e-12);
  // A relation cannot hold for a lone part.
  const QueryScore r = scoreDescriptors(parseLinguisticQuery("find a sphere above a box", v), values);
  EXPECT_EQ(r.score, 0.0);
  ASSERT_FALSE(r.explain.empty());
  EXPECT_EQ(r.explain[0].text, "a sphere above a box");
}

// A condition said again right after itself is scored once (linguistic_score.cpp) but answers as
// if scored each time: its explain entry is repeated, and every aggregation counts it again.
TEST(LinguisticScore, AConditionSaidAgainCountsAgain) {
  const FuzzyPart p = part({{"a1", 1}, {"eps1", 0.7}, {"eps2", 0.7}, {"kx", -0.2}, {"ky", -0.2}});  // roundness 0.7, taper 0.2
  const auto values = describePart(p);
  const LinguisticQuery round = parseLinguisticQuery("find very round shapes", Vocabulary::builtin());
  const LinguisticQuery tapered = parseLinguisticQuery("find tapered shapes", Vocabulary::builtin());
  ASSERT_EQ(round.root.kind, QueryCondition::Kind::kDescriptor);
  ASSERT_EQ(tapered.root.kind, QueryCondition::Kind::kDescriptor);
  LinguisticQuery q = round;
  q.root = QueryCondition{};
  q.root.kind = QueryCondition::Kind::kAnd;
  q.root.children = {round.root, round.root, tapered.root, round.root, round.root};
  const double r = scoreDescriptors(round, values).score;
  const double t = scoreDescriptors(tapered, values).score;
  ASSERT_GT(r, 0.0);
  ASSERT_NE(r, t);
  QueryScore s = scoreDescriptors(q, values);
  ASSERT_EQ(s.explain.size(), 5u);
  for (size_t i : {0u, 1u, 3u, 4u}) {
    EXPECT_EQ(s.explain[i].text, round.root.text);
    EXPECT_DOUBLE_EQ(s.explain[i].score, r);
  }
  EXPECT_DOUBLE_EQ(s.explain[2].score, t);
  EXPECT_DOUBLE_EQ(s.score, std::min(r, t));
  q.aggregation = "mean";
  EXPECT_NEAR(scoreDescriptors(q, values).score, (4 * r + t) / 5, 1e-12);
}

TEST(LinguisticScore, NounsPickTheirPrimitives) {
  const Vocabulary& v = Vocabulary::builtin();
  std::vector<Item> catalogue;
  for (const char* noun : {"sphere", "cube", "cylinder", "cone", "pyramid", "double pyramid", "rod", "plate", "disc"})
    catalogue.push_back({noun, part(v.noun(noun)->params)});
  for (const char* noun : {"sphere", "cube", "cylinder", "cone", "pyramid", "double pyramid", "rod", "plate", "disc"}) {
    const auto ranked = rank(std::string("find a ") + noun, catalogue);
    EXPECT_EQ(ranked[0].first, noun);
    EXPECT_DOUBLE_EQ(ranked[0].second, 1.0) << noun;
    // Rods and discs are cylinders; every other primitive fits only its own noun.
    const size_t ties = std::string(noun) == "cylinder" ? 3 : 1;
    EXPECT_LT(ranked[ties].second, 1.0) << noun << " ties with " << ranked[ties].first;
  }
  // A very bent cylinder: bent cylinders above straight ones above bent boxes.
  auto bent = [&v](const char* noun, double bendness) {
    nlohmann::json params = v.noun(noun)->params;
    params["kv"] = bendness * kPi / (2 * params["a1"].get<double>() * params["a3"].get<double>());
    return part(params);
  };
  const auto ranked = rank("find a very bent cylinder",
                           {{"straight cylinder", bent("cylinder", 0)}, {"bent box", bent("box", 0.9)},
                            {"bent cylinder", bent("cylinder", 0.9)}});
  EXPECT_EQ(ranked[0].first, "bent cylinder");
  EXPECT_DOUBLE_EQ(ranked[0].second, 1.0);
}

// --- shapes: components and relations ------------------------------------------------------------

std::vector<ShapeComponent> componentsOf(const nlohmann::json& tree) {
  const ParsedShape s = parseShapeField({{"kind", "shape"}, {"tree", tree}}, "shape", 100);
  return shapeComponents(*s.tree);
}

nlohmann::json leaf(const char* noun, double x, double y, double z) {
  nlohmann::json params = Vocabulary::builtin().noun(noun)->params;
  return {{"part", {{"params", params}}}, {"transform", {{"translate", {x, y, z}}}}};
}

TEST(LinguisticScore, ShapeComponentsInPreOrder) {
  const auto comps = componentsOf(
      {{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), {{"op", "difference"}, {"children", {leaf("sphere", 1, 0, 0), leaf("rod", 2, 0, 0)}}}}}});
  ASSERT_EQ(comps.size(), 3u);
  EXPECT_EQ(comps[0].path, "tree.children[0]");
  EXPECT_EQ(comps[1].path, "tree.children[1].children[0]");
  EXPECT_EQ(comps[2].path, "tree.children[1].children[1]");
  EXPECT_EQ(comps[1].part.tx, FuzzyNumber::crisp(1));
  EXPECT_EQ(comps[2].descriptors.size(), descriptorNames().size());
}

TEST(LinguisticScore, DescriptorConditionsScoreTheBestComponent) {
  const auto comps = componentsOf({{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), leaf("sphere", 3, 0, 0)}}});
  const QueryScore s = scoreShape(parseLinguisticQuery("find a very round shape", Vocabulary::builtin()), comps);
  EXPECT_DOUBLE_EQ(s.score, 1.0);
  ASSERT_EQ(s.explain.size(), 1u);
  EXPECT_EQ(s.explain[0].component, "tree.children[1]");
  EXPECT_EQ(scoreShape(parseLinguisticQuery("find a bent shape", Vocabulary::builtin()), comps).score, 0.0);
  EXPECT_EQ(scoreShape(parseLinguisticQuery("find a sphere", Vocabulary::builtin()), {}).score, 0.0);
}

TEST(LinguisticScore, CylinderLeftOfACube) {
  const LinguisticQuery q = parseLinguisticQuery("find a cylinder to the left of a cube", Vocabulary::builtin());
  auto scoreOf = [&q](const nlohmann::json& tree) { return scoreShape(q, componentsOf(tree)); };
  const QueryScore left = scoreOf({{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), leaf("cylinder", -3, 0, 0.5)}}});
  const QueryScore right = scoreOf({{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), leaf("cylinder", 3, 0, 0)}}});
  const QueryScore above = scoreOf({{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), leaf("cylinder", -0.5, 3, 0)}}});
  const QueryScore spheres = scoreOf({{"op", "union"}, {"children", {leaf("sphere", 0, 0, 0), leaf("sphere", -3, 0, 0)}}});
  EXPECT_DOUBLE_EQ(left.score, 1.0);
  EXPECT_DOUBLE_EQ(right.score, 0.0);
  EXPECT_DOUBLE_EQ(above.score, 0.0);
  EXPECT_LT(spheres.score, 0.5);
  ASSERT_GE(left.explain.size(), 3u);
  EXPECT_EQ(left.explain[0].text, "a cylinder to the left of a cube");
  EXPECT_EQ(left.explain[0].component, "tree.children[1], tree.children[0]");
  EXPECT_EQ(left.explain[1].text, "cylinder");
  EXPECT_EQ(left.explain[1].component, "tree.children[1]");
  const nlohmann::json j = explainJson(left);
  EXPECT_EQ(j[0], nlohmann::json({{"text", "a cylinder to the left of a cube"}, {"score", 1.0},
                                  {"component", "tree.children[1], tree.children[0]"}}));
  EXPECT_EQ(explainJson(scoreDescriptors(q, {}))[0].count("component"), 0u);
  // One component cannot be in a relation with itself.
  EXPECT_EQ(scoreShape(q, componentsOf(leaf("cylinder", 0, 0, 0))).score, 0.0);
}

// A stored shape naming the previous one twice, 30 deep (2^30 leaves expanded), has the
// components of the bottom one, each once, and scores as it does; a shared subtree's later
// occurrences are the same leaves at the same places, which change no score.
TEST(LinguisticScore, ADagOfSharedShapesListsEachLeafOnce) {
  std::map<std::string, nlohmann::json> stored;
  stored["s0"] = {{"kind", "shape"},
                  {"tree", {{"op", "union"}, {"children", {leaf("cube", 0, 0, 0), leaf("cylinder", -3, 0, 0.5)}}}}};
  for (int k = 1; k <= 30; ++k) {
    const std::string below = "s" + std::to_string(k - 1);
    stored["s" + std::to_string(k)] = {
        {"kind", "shape"}, {"tree", {{"op", "union"}, {"children", {{{"ref", below}}, {{"ref", below}}}}}}};
  }
  int64_t ids = 0;
  const ReferenceResolver resolver = [&](const std::string&, const nlohmann::json& key) -> std::optional<ResolvedReference> {
    auto it = stored.find(key.get<std::string>());
    if (it == stored.end()) return std::nullopt;
    return ResolvedReference{++ids, it->second};
  };
  const auto components = [&](const std::string& name) {
    return shapeComponents(*parseShapeField(stored[name], "shape", 1000, rememberingResolver(resolver)).tree);
  };
  const auto top = components("s30"), bottom = components("s0");
  ASSERT_EQ(top.size(), 2u);
  const LinguisticQuery q = parseLinguisticQuery("find a cylinder to the left of a cube", Vocabulary::builtin());
  EXPECT_DOUBLE_EQ(scoreShape(q, top).score, 1.0);
  EXPECT_DOUBLE_EQ(scoreShape(q, top).score, scoreShape(q, bottom).score);
  // Beside a copy of itself a leaf is in no relation: the expansion scores the same.
  const auto twice = componentsOf({{"op", "union"}, {"children", {leaf("cylinder", 0, 0, 0), leaf("cylinder", 0, 0, 0)}}});
  EXPECT_EQ(scoreShape(q, twice).score, 0.0);
}

TEST(LinguisticScore, SphereAbout3AboveABox) {
  const LinguisticQuery q = parseLinguisticQuery("find a sphere about 3 above a box", Vocabulary::builtin());
  auto scoreOf = [&q](double y) {
    return scoreShape(q, componentsOf({{"op", "union"}, {"children", {leaf("box", 0, 0, 0), leaf("sphere", 0, y, 0)}}})).score;
  };
  EXPECT_DOUBLE_EQ(scoreOf(3), 1.0);
  EXPECT_NEAR(scoreOf(3.15), 0.5, 1e-12);  // the triangle of "about 3" (spread 0.3)
  EXPECT_DOUBLE_EQ(scoreOf(6), 0.0);
  EXPECT_DOUBLE_EQ(scoreOf(-3), 0.0);
}

TEST(LinguisticScore, CentreDistanceOfFuzzyPlacements) {
  const FuzzyPart a = part({{"a1", 1}}, {{"translate", {{{"tri", {2, 3, 4}}}, 0, 0}}});
  const FuzzyPart b = part({{"a1", 1}}, {{"translate", {0, 4, 0}}});
  const FuzzyNumber d = centreDistance(a, b);
  EXPECT_NEAR(d.core().lo, 5.0, 1e-12);
  EXPECT_NEAR(d.support().lo, std::hypot(2, 4), 1e-12);
  EXPECT_NEAR(d.support().hi, std::hypot(4, 4), 1e-12);
  const FuzzyPart c = part({{"a1", 1}}, {{"translate", {{{"tri", {-1, 0, 1}}}, 0, 0}}});
  EXPECT_NEAR(centreDistance(c, part({{"a1", 1}})).support().lo, 0.0, 1e-12);
}

}  // namespace
}  // namespace fsdb
