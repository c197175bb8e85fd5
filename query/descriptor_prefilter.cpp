// See query/descriptor_prefilter.h.
#include "query/descriptor_prefilter.h"

#include <algorithm>
#include <iterator>

namespace fsdb {
namespace {

using Kind = PrefilterPlan::Kind;

PrefilterPlan leaf(Kind kind) {
  PrefilterPlan plan;
  plan.kind = kind;
  return plan;
}

// A kAnd / kOr of already simplified children.
PrefilterPlan combine(Kind kind, std::vector<PrefilterPlan> children) {
  const Kind absorbing = kind == Kind::kAnd ? Kind::kNone : Kind::kAll;  // decides the whole node
  const Kind neutral = kind == Kind::kAnd ? Kind::kAll : Kind::kNone;    // drops out
  PrefilterPlan plan = leaf(kind);
  for (PrefilterPlan& child : children) {
    if (child.kind == absorbing) return leaf(absorbing);
    if (child.kind == neutral) continue;
    if (child.kind == kind) {  // (a and b) and c: one level
      for (PrefilterPlan& grandchild : child.children) plan.children.push_back(std::move(grandchild));
    } else {
      plan.children.push_back(std::move(child));
    }
  }
  if (plan.children.empty()) return leaf(neutral);
  if (plan.children.size() == 1) return std::move(plan.children.front());
  return plan;
}

PrefilterPlan planOf(const QueryCondition& condition, bool andNeedsAll, bool forParts) {
  switch (condition.kind) {
    case QueryCondition::Kind::kDescriptor: {
      PrefilterPlan plan = leaf(Kind::kOverlap);
      plan.test = supportTest(condition.descriptor, condition.set);
      return plan;
    }
    case QueryCondition::Kind::kAnd:
    case QueryCondition::Kind::kOr: {
      std::vector<PrefilterPlan> children;
      for (const QueryCondition& child : condition.children) children.push_back(planOf(child, andNeedsAll, forParts));
      const bool all = condition.kind == QueryCondition::Kind::kAnd && andNeedsAll;
      return combine(all ? Kind::kAnd : Kind::kOr, std::move(children));
    }
    case QueryCondition::Kind::kNot:
      return leaf(Kind::kAll);
    case QueryCondition::Kind::kRelation:
      return leaf(forParts ? Kind::kNone : Kind::kAll);
  }
  return leaf(Kind::kAll);
}

std::vector<int64_t> intersect(const std::vector<int64_t>& a, const std::vector<int64_t>& b) {
  std::vector<int64_t> out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

std::vector<int64_t> unite(const std::vector<int64_t>& a, const std::vector<int64_t>& b) {
  std::vector<int64_t> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

SupportTest supportTest(const std::string& descriptor, const FuzzyNumber& set) {
  const Interval support = set.support();
  SupportTest test;
  test.descriptor = descriptor;
  test.lo = support.lo;
  test.hi = support.hi;
  test.loIncluded = set.membership(support.lo) > 0;
  test.hiIncluded = set.membership(support.hi) > 0;
  test.wideStrict = set.cardinality() > 0;
  return test;
}

bool admits(const SupportTest& test, double slo, double shi) {
  if (slo == shi) {
    const double x = slo;
    return (x > test.lo || (x == test.lo && test.loIncluded)) && (x < test.hi || (x == test.hi && test.hiIncluded));
  }
  if (test.wideStrict) return slo < test.hi && shi > test.lo;
  return slo <= test.hi && shi >= test.lo;
}

bool aggregationNeedsAll(const std::string& aggregation) {
  // Every t-norm T has T(0, x) = 0; the names are those of the operator catalogue and the
  // common spellings of the product.
  static const std::vector<std::string> tnorms = {"min", "zadeh", "product", "algebraic", "lukasiewicz",
                                                  "einstein", "hamacher", "dombi", "yager", "weber",
                                                  "dubois_prade", "drastic"};
  return std::find(tnorms.begin(), tnorms.end(), aggregation) != tnorms.end();
}

PrefilterPlan prefilterPlan(const LinguisticQuery& query, const std::string& kind) {
  return planOf(query.root, aggregationNeedsAll(query.aggregation), kind == "part");
}

std::vector<int64_t> runPrefilter(const PrefilterPlan& plan, const OverlapSource& overlap, const AllSource& all) {
  switch (plan.kind) {
    case Kind::kAll:
      return all();
    case Kind::kNone:
      return {};
    case Kind::kOverlap:
      return overlap(plan.test);
    case Kind::kAnd: {
      std::vector<int64_t> ids = runPrefilter(plan.children.front(), overlap, all);
      for (size_t i = 1; i < plan.children.size() && !ids.empty(); ++i)
        ids = intersect(ids, runPrefilter(plan.children[i], overlap, all));
      return ids;
    }
    case Kind::kOr: {
      std::vector<int64_t> ids;
      for (const PrefilterPlan& child : plan.children) ids = unite(ids, runPrefilter(child, overlap, all));
      return ids;
    }
  }
  return all();
}

nlohmann::json prefilterPlanJson(const PrefilterPlan& plan) {
  switch (plan.kind) {
    case Kind::kAll:
      return {{"all", true}};
    case Kind::kNone:
      return {{"none", true}};
    case Kind::kOverlap:
      return {{"overlap",
               {{"descriptor", plan.test.descriptor}, {"lo", plan.test.lo}, {"hi", plan.test.hi},
                {"lo_included", plan.test.loIncluded}, {"hi_included", plan.test.hiIncluded},
                {"wide_strict", plan.test.wideStrict}}}};
    case Kind::kAnd:
    case Kind::kOr: {
      nlohmann::json children = nlohmann::json::array();
      for (const PrefilterPlan& child : plan.children) children.push_back(prefilterPlanJson(child));
      return {{plan.kind == Kind::kAnd ? "and" : "or", children}};
    }
  }
  return nullptr;
}

}  // namespace fsdb
