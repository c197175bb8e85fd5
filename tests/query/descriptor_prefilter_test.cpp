// query/descriptor_prefilter.h: the plan of each condition kind, its simplification, and
// runPrefilter's set algebra against explicit sources.
#include "query/descriptor_prefilter.h"

#include <gtest/gtest.h>

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
  EXPECT_EQ(prefilterPlanJson(plan),
            nlohmann::json::parse(R"({"overlap":{"descriptor":"bendness","lo":0.1,"hi":0.4}})"));
}

TEST(DescriptorPrefilter, AndOrNotRelation) {
  const QueryCondition bent = descriptor("bendness", 0.1, 0.25, 0.4), big = descriptor("size", 0.6, 0.8, 1.0);
  QueryCondition relation = node(K::kRelation, {bent, big});
  relation.direction = "left";
  const QueryCondition notBig = node(K::kNot, {big});

  EXPECT_EQ(prefilterPlanJson(prefilterPlan(query(node(K::kAnd, {bent, big})), "part")).dump(),
            R"({"and":[{"overlap":{"descriptor":"bendness","hi":0.4,"lo":0.1}},)"
            R"({"overlap":{"descriptor":"size","hi":1.0,"lo":0.6}}]})");
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
}

TEST(DescriptorPrefilter, AggregationsThatNeedEveryChild) {
  EXPECT_TRUE(aggregationNeedsAll("min"));
  EXPECT_TRUE(aggregationNeedsAll("product"));
  EXPECT_FALSE(aggregationNeedsAll("mean"));
  EXPECT_FALSE(aggregationNeedsAll("something new"));
}

TEST(DescriptorPrefilter, RunIntersectsAndUnites) {
  const OverlapSource overlap = [](const std::string& d, double, double) -> std::vector<int64_t> {
    if (d == "bendness") return {1, 3, 5, 7};
    if (d == "size") return {3, 4, 5};
    return {};
  };
  int allCalls = 0;
  const AllSource all = [&allCalls] {
    ++allCalls;
    return std::vector<int64_t>{1, 2, 3, 4, 5, 6, 7};
  };
  const QueryCondition bent = descriptor("bendness", 0, 0.5, 1), big = descriptor("size", 0, 0.5, 1);
  EXPECT_EQ(runPrefilter(prefilterPlan(query(node(K::kAnd, {bent, big})), "part"), overlap, all),
            (std::vector<int64_t>{3, 5}));
  EXPECT_EQ(runPrefilter(prefilterPlan(query(node(K::kOr, {bent, big})), "part"), overlap, all),
            (std::vector<int64_t>{1, 3, 4, 5, 7}));
  EXPECT_EQ(allCalls, 0);
  EXPECT_EQ(runPrefilter(prefilterPlan(query(node(K::kNot, {bent})), "part"), overlap, all).size(), 7u);
  EXPECT_EQ(allCalls, 1);
  EXPECT_TRUE(runPrefilter(prefilterPlan(query(node(K::kAnd, {bent, descriptor("twistness", 0, 0, 1)})), "part"),
                           overlap, all)
                  .empty());
}

}  // namespace
}  // namespace fsdb
