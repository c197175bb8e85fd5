// query/linguistic/descriptor_prefilter.h: the plan of each condition kind, its simplification, and
// runPrefilter's set algebra against explicit sources.
#include "query/linguistic/descriptor_prefilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <random>

#include "geometry/fuzzy/fuzzy_similarity.h"
#include "tests/testing/random_fuzzy.h"

namespace fsdb {
namespace {

QueryCondition descriptor(const std::string& name, double l, double m, double r) {
  QueryCondition c;
  c.kind = QueryCondition::Kind::kDescriptor;
  c.descriptor = name;
  c.set = FuzzyNumber::triangular(l, m, r);
  return c;
}

QueryCondition node(QueryCondition::Kind kind, std::vector<QueryCondition> children) {
  QueryCondition c;
  c.kind = kind;
  c.children = std::move(children);
  return c;
}

LinguisticQuery query(QueryCondition root, const std::string& aggregation = "min") {
  LinguisticQuery q;
  q.root = std::move(root);
  q.aggregation = aggregation;
  return q;
}

using K = QueryCondition::Kind;

TEST(DescriptorPrefilter, DescriptorIsTheSupportOfItsSet) {
  const PrefilterPlan plan = prefilterPlan(query(descriptor("bendness", 0.1, 0.25, 0.4)), "part");
  EXPECT_EQ(prefilterPlanJson(plan), nlohmann::json::parse(R"({"overlap":{"descriptor":"bendness","lo":0.1,"hi":0.4,
            "lo_included":false,"hi_included":false,"wide_strict":true}})"));
}

TEST(DescriptorPrefilter, SupportTestEnds) {
  // The plain set mu(d) = d: a crisp 0 scores 0 and is not admitted; any d > 0 is.
  const SupportTest plain = supportTest("bendness", FuzzyNumber::fromPoints({{0, 0}, {1, 1}}));
  EXPECT_FALSE(admits(plain, 0, 0));
  EXPECT_TRUE(admits(plain, 1e-9, 1e-9));
  EXPECT_TRUE(admits(plain, 1, 1));  // mu(1) = 1: the end is included
  EXPECT_TRUE(admits(plain, 0, 0.01));
  EXPECT_FALSE(admits(plain, -0.5, 0));  // touches at one point: |A∩B| = 0
  // A crisp set (area 0): S is the height of A∩B, so touching wide values count.
  const SupportTest crisp = supportTest("size", FuzzyNumber::crisp(0.5));
  EXPECT_TRUE(admits(crisp, 0.5, 0.5));
  EXPECT_TRUE(admits(crisp, 0.2, 0.5));
  EXPECT_FALSE(admits(crisp, 0.2, 0.49));
}

// The derivation principle: whatever scores > 0 passes the support test, for random values
// (crisp, triangles, trapezoids, vertical sides) and sets.
TEST(DescriptorPrefilter, EverythingThatScoresPassesItsSupportTest) {
  std::mt19937 rng(17);
  auto random = [&rng](bool maybeCrisp) {
    const double u = testing::uniform(rng, 0, 1);
    if (maybeCrisp && u < 0.3) return FuzzyNumber::crisp(std::round(testing::uniform(rng, -8, 8)));
    if (u < 0.6) return testing::randomTriangular(rng, true);
    if (u < 0.8) return testing::randomTrapezoidal(rng);
    return testing::randomConvexPoints(rng);
  };
  int positive = 0;
  for (int i = 0; i < 20000; ++i) {
    const FuzzyNumber value = random(true), set = random(i % 4 == 0);
    const Interval s = value.support();
    const bool passes = admits(supportTest("d", set), s.lo, s.hi);
    if (similarity(value, set) > 0) {
      ++positive;
      EXPECT_TRUE(passes) << "value [" << s.lo << ", " << s.hi << "] set [" << set.support().lo << ", "
                          << set.support().hi << "]";
    }
  }
  EXPECT_GT(positive, 1000);
}

TEST(DescriptorPrefilter, AndOrNotRelation) {
  const QueryCondition bent = descriptor("bendness", 0.1, 0.25, 0.4), big = descriptor("size", 0.6, 0.8, 1.0);
  QueryCondition relation = node(K::kRelation, {bent, big});
  relation.direction = "left";
  const QueryCondition notBig = node(K::kNot, {big});

  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, big})), "part")),
            nlohmann::json({{"and", {prefilterPlanJson(prefilterPlan(query(bent), "part")),
                                     prefilterPlanJson(prefilterPlan(query(big), "part"))}}}));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kOr, {bent, big})), "part")).begin().key(), "or");
  // A mean is > 0 when one child is: kAnd needs any child.
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, big}), "mean"), "part")).begin().key(), "or");
  // not: no filter; under an and it drops out, under an or it makes everything a candidate.
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(notBig), "part")), nlohmann::json({{"all", true}}));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, notBig})), "part")),
            prefilterPlanJson(prefilterPlan(query(bent), "part")));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kOr, {bent, notBig})), "part")),
            nlohmann::json({{"all", true}}));
  // A relation: nothing for lone parts, no filter for shapes.
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(relation), "part")), nlohmann::json({{"none", true}}));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(relation), "shape")), nlohmann::json({{"all", true}}));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, relation})), "part")),
            nlohmann::json({{"none", true}}));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kOr, {bent, relation})), "part")),
            prefilterPlanJson(prefilterPlan(query(bent), "part")));
  // Nested ands flatten.
  const PrefilterPlan nested =
      prefilterPlan(query(node(K::kAnd, {bent, node(K::kAnd, {big, descriptor("twistness", 0, 0, 0.2)})})), "shape");
  EXPECT_EQ(nested.kind, PrefilterPlan::Kind::kAnd);
  EXPECT_EQ(nested.children.size(), 3u);
  // The same leaf twice is one (a long text of repeated words asks the index once); the same
  // descriptor with another set stays.
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, big, bent, node(K::kAnd, {big, bent})})), "part")),
            prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, big})), "part")));
  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kOr, {big, big})), "part")),
            prefilterPlanJson(prefilterPlan(query(big), "part")));
  EXPECT_EQ(prefilterPlan(query(node(K::kAnd, {bent, descriptor("bendness", 0.5, 0.6, 0.7)})), "part").children.size(), 2u);
}

TEST(DescriptorPrefilter, AggregationsThatNeedEveryChild) {
  EXPECT_TRUE(aggregationNeedsAll("min"));
  EXPECT_TRUE(aggregationNeedsAll("product"));
  EXPECT_FALSE(aggregationNeedsAll("mean"));
  EXPECT_FALSE(aggregationNeedsAll("something new"));
}

std::vector<int64_t> idsOf(const std::vector<Candidate>& candidates) {
  std::vector<int64_t> ids;
  for (const Candidate& c : candidates) ids.push_back(c.id);
  return ids;
}

// Index rows of one descriptor: an object's support [lo, hi], or pending.
struct IndexRow {
  int64_t id;
  double lo, hi;
  bool pending;
};

// An overlap source over fixed rows per descriptor, bounded as the search bounds them.
OverlapSource overlapOf(const std::map<std::string, std::vector<IndexRow>>& rowsByDescriptor) {
  return [rowsByDescriptor](const PrefilterPlan& leaf) {
    std::vector<Candidate> out;
    const auto it = rowsByDescriptor.find(leaf.test.descriptor);
    if (it != rowsByDescriptor.end())
      for (const IndexRow& r : it->second)
        out.push_back({r.id, scoreBound(leaf, r.lo, r.hi, r.pending), coverageBound(leaf, r.lo, r.hi, r.pending)});
    return out;
  };
}

TEST(DescriptorPrefilter, RunIntersectsAndUnites) {
  // bendness rows: crisp values (id 1: 0.5, id 3: 0.25 twice for two components, id 5: 1, id 7:
  // pending); size rows: wide [0, 1] for 3, 4, 5.
  const OverlapSource overlap = overlapOf(
      {{"bendness", {{1, 0.5, 0.5, false}, {3, 0.25, 0.25, false}, {3, 0.75, 0.75, false}, {5, 1, 1, false}, {7, 0, 0, true}}},
       {"size", {{3, 0, 1, false}, {4, 0, 1, false}, {5, 0, 0.5, false}}}});
  int allCalls = 0;
  const AllSource all = [&allCalls] {
    ++allCalls;
    return std::vector<int64_t>{1, 2, 3, 4, 5, 6, 7};
  };
  const QueryCondition bent = descriptor("bendness", 0, 0.5, 1), big = descriptor("size", 0, 0.5, 1);
  const std::vector<Candidate> both = runPrefilter(prefilterPlan(query(node(K::kAnd, {bent, big})), "part"), overlap, all);
  EXPECT_EQ(idsOf(both), (std::vector<int64_t>{3, 5}));
  // Bounds: 3 = min(max(μ(0.25), μ(0.75)) = 0.5, ∫_0^1 μ / |B| = 1); 5 = min(μ(1) = 0, 0.5).
  EXPECT_NEAR(both[0].bound, 0.5, 1e-8);
  EXPECT_NEAR(both[1].bound, 0.0, 1e-8);
  const std::vector<Candidate> either = runPrefilter(prefilterPlan(query(node(K::kOr, {bent, big})), "part"), overlap, all);
  EXPECT_EQ(idsOf(either), (std::vector<int64_t>{1, 3, 4, 5, 7}));
  EXPECT_NEAR(either[0].bound, 1.0, 1e-8);  // μ(0.5) = 1
  EXPECT_EQ(either[4].bound, 1.0);          // pending
  EXPECT_EQ(allCalls, 0);
  // One row per object: a lone overlap comes back as the source gives it (here, 3 twice).
  EXPECT_EQ(idsOf(runPrefilter(prefilterPlan(query(bent), "part"), overlap, all, true)),
            (std::vector<int64_t>{1, 3, 3, 5, 7}));
  const std::vector<Candidate> merged = runPrefilter(prefilterPlan(query(bent), "part"), overlap, all);
  EXPECT_EQ(idsOf(merged), (std::vector<int64_t>{1, 3, 5, 7}));
  EXPECT_NEAR(merged[1].bound, 0.5, 1e-8);  // the better of 3's two rows
  EXPECT_EQ(runPrefilter(prefilterPlan(query(node(K::kNot, {bent})), "part"), overlap, all).size(), 7u);
  EXPECT_EQ(allCalls, 1);
  EXPECT_TRUE(runPrefilter(prefilterPlan(query(node(K::kAnd, {bent, descriptor("twistness", 0, 0, 1)})), "part"),
                           overlap, all)
                  .empty());
}

// Coverage bounds through the plan: a said leaf's crisp rows 0, wide rows their score bound, a
// pending object 1; "and" the least, "or" the largest, an object missing from a said child 0 there.
TEST(DescriptorPrefilter, CoverageBoundsFollowThePlan) {
  const OverlapSource overlap =
      overlapOf({{"bendness", {{1, 0.5, 0.5, false}, {3, 0.25, 0.75, false}, {7, 0, 0, true}}},
                 {"size", {{1, 0, 1, false}, {3, 0.5, 0.5, false}, {4, 0.25, 0.75, false}}}});
  const AllSource all = [] { return std::vector<int64_t>{1, 2, 3, 4, 5, 6, 7}; };
  const QueryCondition bent = descriptor("bendness", 0, 0.5, 1), big = descriptor("size", 0, 0.5, 1);
  const PrefilterPlan plan = prefilterPlan(query(bent), "part");
  ASSERT_TRUE(plan.said);
  const std::vector<Candidate> one = runPrefilter(plan, overlap, all);
  ASSERT_EQ(idsOf(one), (std::vector<int64_t>{1, 3, 7}));
  EXPECT_EQ(one[0].tie, 0);                   // crisp 0.5: in the core, spans nothing
  EXPECT_EQ(one[1].tie, one[1].bound);        // wide: its score bound
  EXPECT_EQ(one[2].tie, 1);                   // pending
  const std::vector<Candidate> both = runPrefilter(prefilterPlan(query(node(K::kAnd, {bent, big})), "part"), overlap, all);
  ASSERT_EQ(idsOf(both), (std::vector<int64_t>{1, 3}));
  EXPECT_EQ(both[0].tie, 0);                  // min(crisp bend 0, wide size)
  EXPECT_EQ(both[1].tie, 0);                  // min(wide bend, crisp size 0)
  const std::vector<Candidate> either = runPrefilter(prefilterPlan(query(node(K::kOr, {bent, big})), "part"), overlap, all);
  ASSERT_EQ(idsOf(either), (std::vector<int64_t>{1, 3, 4, 7}));
  EXPECT_NEAR(either[0].tie, 1, 1e-8);        // max(0, wide size over the whole set)
  EXPECT_GT(either[2].tie, 0);                // 4: wide size; missing from bendness (0 there)
  EXPECT_EQ(either[2].tie, coverageBound(prefilterPlan(query(big), "part"), 0.25, 0.75, false));
  // A noun's conditions are not said: bound 1, and an object missing from one may still cover 1.
  QueryCondition cylinder = big;
  cylinder.noun = "cylinder";
  const PrefilterPlan nounPlan = prefilterPlan(query(node(K::kOr, {bent, cylinder})), "part");
  EXPECT_EQ(absentCoverage(nounPlan), 1);
  EXPECT_EQ(absentCoverage(prefilterPlan(query(node(K::kOr, {bent, big})), "part")), 0);
  const std::vector<Candidate> withNoun = runPrefilter(nounPlan, overlap, all);
  for (const Candidate& c : withNoun) EXPECT_EQ(c.tie, 1) << c.id;
}

TEST(DescriptorPrefilter, MembershipIntegral) {
  const FuzzyNumber t = FuzzyNumber::trapezoidal(0, 1, 2, 4);
  EXPECT_DOUBLE_EQ(membershipIntegral(t, -10, 10), t.cardinality());
  EXPECT_DOUBLE_EQ(membershipIntegral(t, 0, 1), 0.5);
  EXPECT_DOUBLE_EQ(membershipIntegral(t, 1.5, 3), 0.5 + 0.75);
  EXPECT_DOUBLE_EQ(membershipIntegral(t, 5, 6), 0.0);
  EXPECT_DOUBLE_EQ(membershipIntegral(FuzzyNumber::crisp(1), 0, 2), 0.0);
}

// Every bound is >= the similarity it bounds, for random values and sets.
TEST(DescriptorPrefilter, BoundsAreAtLeastTheScores) {
  std::mt19937 rng(23);
  int tight = 0;
  for (int i = 0; i < 20000; ++i) {
    const double u = testing::uniform(rng, 0, 1);
    const FuzzyNumber value = u < 0.3 ? FuzzyNumber::crisp(testing::uniform(rng, -8, 8))
                              : u < 0.7 ? testing::randomTriangular(rng, true)
                                        : testing::randomConvexPoints(rng);
    const FuzzyNumber set = i % 5 == 0 ? FuzzyNumber::crisp(std::round(testing::uniform(rng, -8, 8)))
                                       : testing::randomTrapezoidal(rng);
    const PrefilterPlan leaf = prefilterPlan(query(descriptor("d", 0, 0, 0)), "part");
    PrefilterPlan plan = leaf;
    plan.test = supportTest("d", set);
    plan.set = set;
    const Interval s = value.support();
    const double bound = scoreBound(plan, s.lo, s.hi, false);
    const double score = similarity(value, set);
    EXPECT_GE(bound, score) << "value [" << s.lo << ", " << s.hi << "]";
    // The coverage bound of a said leaf bounds |A∩B| / |B|; a leaf that is not said bounds nothing.
    plan.said = true;
    EXPECT_GE(coverageBound(plan, s.lo, s.hi, false), coverage(value, set)) << "value [" << s.lo << ", " << s.hi << "]";
    if (value.isCrisp() && set.cardinality() > 0) {
      EXPECT_EQ(coverageBound(plan, s.lo, s.hi, false), 0);
    }
    plan.said = false;
    EXPECT_EQ(coverageBound(plan, s.lo, s.hi, false), 1);
    if (score > 0 && bound < 1) ++tight;
    // A noun's default scores its expected membership: bounded alone, and both ways when a said
    // leaf and a noun's were merged into one.
    plan.bySimilarity = false;
    plan.byExpectedMembership = true;
    const double defaultScore = expectedMembership(value, set);
    EXPECT_GE(scoreBound(plan, s.lo, s.hi, false), defaultScore) << "value [" << s.lo << ", " << s.hi << "]";
    plan.bySimilarity = true;
    EXPECT_GE(scoreBound(plan, s.lo, s.hi, false), std::max(score, defaultScore));
    // Scored relative to a meeting height h (QueryCondition::relativeTo): min(1, s / h).
    plan.relativeTo = testing::uniform(rng, 0.1, 1.0);
    EXPECT_GE(scoreBound(plan, s.lo, s.hi, false), std::min(1.0, std::max(score, defaultScore) / plan.relativeTo));
    plan.relativeTo = 1.0;
  }
  EXPECT_GT(tight, 1000);
}

// The plan marks a noun's defaults for the expected membership they score, and a leaf said
// and also a noun's default (merged) for both.
TEST(DescriptorPrefilter, NounDefaultsAreBoundedByTheirExpectedMembership) {
  const LinguisticQuery q = parseLinguisticQuery("find a small knob", activeVocabulary());
  const PrefilterPlan plan = prefilterPlan(q, "part");
  int defaults = 0, said = 0;
  std::function<void(const PrefilterPlan&)> walk = [&](const PrefilterPlan& p) {
    if (p.kind == PrefilterPlan::Kind::kOverlap) {
      EXPECT_NE(p.bySimilarity, p.byExpectedMembership);
      defaults += p.byExpectedMembership;
      said += p.said;
      EXPECT_EQ(p.said, p.bySimilarity);
    }
    for (const PrefilterPlan& c : p.children) walk(c);
  };
  walk(plan);
  EXPECT_EQ(said, 1);      // small
  EXPECT_EQ(defaults, 2);  // the knob's roundness and size
  // A narrow size in the knob's core scores 1, and its piece of the level scan is bounded by 1.
  const FuzzyNumber knobSize = FuzzyNumber::trapezoidal(0, 0, 0.3, 0.45);
  PrefilterPlan leaf;
  leaf.kind = PrefilterPlan::Kind::kOverlap;
  leaf.test = supportTest("size", knobSize);
  leaf.set = knobSize;
  leaf.bySimilarity = false;
  leaf.byExpectedMembership = true;
  EXPECT_GE(scoreBound(leaf, 0.1, 0.12, false), 1.0);
  for (const LevelPiece& piece : levelPieces(leaf, 0.02, 0.0, 0.28)) EXPECT_GE(piece.bound, 1.0);
}

// levelPieces: the pieces cover the range exactly, in order, and bound the score of every value
// whose support starts in them (crisp values: width 0; wide values: width <= maxWidth); the
// pieces in the set's core and outside it are told apart (bounds below 1 exist).
TEST(DescriptorPrefilter, LevelPiecesCoverTheRangeAndBoundTheirValues) {
  std::mt19937 rng(31);
  int below1 = 0;
  for (int i = 0; i < 3000; ++i) {
    const FuzzyNumber set = i % 7 == 0 ? FuzzyNumber::crisp(std::round(testing::uniform(rng, -4, 4)))
                            : i % 7 == 1 ? FuzzyNumber::trapezoidal(0, 0, 0.1, 0.3)
                                         : testing::randomTrapezoidal(rng);
    PrefilterPlan leaf = prefilterPlan(query(descriptor("d", 0, 0, 0)), "part");
    leaf.test = supportTest("d", set);
    leaf.set = set;
    const bool crisp = i % 2 == 0;
    const double maxWidth = crisp ? 0 : std::ldexp(1.0, std::uniform_int_distribution<int>(-8, 2)(rng));
    const Interval support = set.support();
    const double fromLo = support.lo - maxWidth, toLo = support.hi;
    const std::vector<LevelPiece> pieces = levelPieces(leaf, maxWidth, fromLo, toLo);
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front().fromLo, fromLo);
    EXPECT_EQ(pieces.back().toLo, toLo);
    for (size_t k = 0; k < pieces.size(); ++k) {
      EXPECT_LE(pieces[k].fromLo, pieces[k].toLo);
      if (k > 0) {
        EXPECT_EQ(pieces[k].fromLo, std::nextafter(pieces[k - 1].toLo, 1e300));
      }
      if (pieces[k].bound < 1) ++below1;
    }
    for (int v = 0; v < 20; ++v) {
      const double lo = testing::uniform(rng, fromLo, toLo);
      const double width = crisp ? 0 : maxWidth * testing::uniform(rng, 0.01, 0.999);
      const FuzzyNumber value = crisp ? FuzzyNumber::crisp(lo)
                                      : FuzzyNumber::triangular(lo, lo + width * testing::uniform(rng, 0, 1), lo + width);
      const Interval s = value.support();
      const auto in = std::find_if(pieces.begin(), pieces.end(),
                                   [&](const LevelPiece& p) { return s.lo >= p.fromLo && s.lo <= p.toLo; });
      ASSERT_NE(in, pieces.end());
      EXPECT_GE(in->bound, similarity(value, set)) << "value [" << s.lo << ", " << s.hi << "]";
      EXPECT_GE(in->bound, scoreBound(leaf, s.lo, s.hi, false));
    }
  }
  EXPECT_GT(below1, 3000);
}

// Wide pieces are cut at quarters of the width class before each alpha-cut end, so a piece whose
// rows cannot reach the core gets a bound below 1 even when the class is wider than the set: "very"
// (area 0.35) against widths up to 0.5, the rows starting at 0.3 reach 0.8 at most.
TEST(DescriptorPrefilter, WidePiecesThatCannotReachTheCoreBoundBelowOne) {
  PrefilterPlan leaf = prefilterPlan(query(descriptor("d", 0, 0, 0)), "part");
  leaf.set = FuzzyNumber::trapezoidal(0.55, 0.75, 1, 1);
  leaf.test = supportTest("d", leaf.set);
  const std::vector<LevelPiece> pieces = levelPieces(leaf, 0.5, 0.05, 1.0);
  const auto at = [&](double x) {
    return *std::find_if(pieces.begin(), pieces.end(), [&](const LevelPiece& p) { return x >= p.fromLo && x <= p.toLo; });
  };
  EXPECT_LT(at(0.3).bound, 0.7);  // reach <= 0.875: ∫μ <= 0.225 of 0.35
  EXPECT_LT(at(0.1).bound, 0.4);
  EXPECT_EQ(at(0.55).bound, 1.0);  // a row [0.55, 1.0] scores 1
  // Every value starting in a piece still scores at most its bound.
  for (double lo = 0.05; lo < 1.0; lo += 0.01)
    for (double width : {0.26, 0.3, 0.4, 0.5}) {
      const FuzzyNumber value = FuzzyNumber::triangular(lo, lo + width / 2, lo + width);
      EXPECT_GE(at(lo).bound, similarity(value, leaf.set)) << lo << " " << width;
    }
}

// LevelPiece::order says how μ_set runs over a crisp piece, so the search may read it best values
// first (kRising, kFalling) or in id order (kFlat); crispLevelBound bounds every value of a
// sub-range, as the search narrows a piece it pages through.
TEST(DescriptorPrefilter, LevelPieceOrderIsHowTheMembershipRuns) {
  std::mt19937 rng(37);
  int rising = 0, falling = 0, flat = 0;
  for (int i = 0; i < 2000; ++i) {
    const FuzzyNumber set = i % 5 == 0 ? FuzzyNumber::fromPoints({{0, 0}, {0.3, 0.6}, {0.5, 0.2}, {0.7, 1}, {1, 0}})
                                       : testing::randomTrapezoidal(rng);
    PrefilterPlan leaf = prefilterPlan(query(descriptor("d", 0, 0, 0)), "part");
    leaf.test = supportTest("d", set);
    leaf.set = set;
    const Interval support = set.support();
    for (const LevelPiece& piece : levelPieces(leaf, 0, support.lo, support.hi)) {
      double previous = set.membership(piece.fromLo);
      for (int k = 1; k <= 16; ++k) {
        const double x = k == 16 ? piece.toLo : piece.fromLo + (piece.toLo - piece.fromLo) * k / 16.0;
        const double mu = set.membership(x);
        if (piece.order == LevelOrder::kRising) {
          EXPECT_GE(mu, previous) << x;
        } else if (piece.order == LevelOrder::kFalling) {
          EXPECT_LE(mu, previous) << x;
        } else if (piece.order == LevelOrder::kFlat) {
          EXPECT_EQ(mu, previous) << x;
        }
        previous = mu;
        const double from = testing::uniform(rng, piece.fromLo, x);
        EXPECT_GE(crispLevelBound(leaf, from, x), mu);
        EXPECT_GE(crispLevelBound(leaf, from, x), scoreBound(leaf, x, x, false));
      }
      rising += piece.order == LevelOrder::kRising;
      falling += piece.order == LevelOrder::kFalling;
      flat += piece.order == LevelOrder::kFlat;
    }
    // Wide pieces have no order.
    for (const LevelPiece& piece : levelPieces(leaf, 0.25, support.lo - 0.25, support.hi))
      EXPECT_EQ(piece.order, LevelOrder::kAny);
  }
  EXPECT_GT(rising, 1000);
  EXPECT_GT(falling, 1000);
  EXPECT_GT(flat, 1000);
  // A trapezoid: rising up to its core, flat over it, falling after.
  PrefilterPlan leaf = prefilterPlan(query(descriptor("d", 0, 0, 0)), "part");
  leaf.set = FuzzyNumber::trapezoidal(0.55, 0.75, 1, 1.2);
  leaf.test = supportTest("d", leaf.set);
  const std::vector<LevelPiece> pieces = levelPieces(leaf, 0, 0.55, 1.2);
  const auto at = [&](double x) {
    return std::find_if(pieces.begin(), pieces.end(), [&](const LevelPiece& p) { return x >= p.fromLo && x <= p.toLo; })
        ->order;
  };
  EXPECT_EQ(at(0.6), LevelOrder::kRising);
  EXPECT_EQ(at(0.8), LevelOrder::kFlat);
  EXPECT_EQ(at(1.0), LevelOrder::kFlat);
  EXPECT_EQ(at(1.1), LevelOrder::kFalling);
}

}  // namespace
}  // namespace fsdb
