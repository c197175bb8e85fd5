// See query/linguistic/descriptor_prefilter.h.
#include "query/linguistic/descriptor_prefilter.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

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
  // a and a, a or a: a, for bounds as for candidates (a 10,000-word text of repeated words asked
  // the index once per word). Only leaves are compared: they are most of any long text.
  const auto add = [&plan](PrefilterPlan&& c) {
    if (c.kind == Kind::kOverlap)
      for (PrefilterPlan& seen : plan.children)
        if (seen.kind == Kind::kOverlap && seen.test.descriptor == c.test.descriptor && seen.set == c.set) {
          // Said once, said: its coverage bound stays valid for both (the same test fails both).
          seen.said = seen.said || c.said;
          seen.bySimilarity = seen.bySimilarity || c.bySimilarity;
          seen.byExpectedMembership = seen.byExpectedMembership || c.byExpectedMembership;
          seen.relativeTo = std::min(seen.relativeTo, c.relativeTo);
          return;
        }
    plan.children.push_back(std::move(c));
  };
  for (PrefilterPlan& child : children) {
    if (child.kind == absorbing) return leaf(absorbing);
    if (child.kind == neutral) continue;
    if (child.kind == kind) {  // (a and b) and c: one level
      for (PrefilterPlan& grandchild : child.children) add(std::move(grandchild));
    } else {
      add(std::move(child));
    }
  }
  if (plan.children.empty()) return leaf(neutral);
  if (plan.children.size() == 1) return std::move(plan.children.front());
  return plan;
}

// said: no noun's node above (QueryScore::coverage reads the leaves below).
PrefilterPlan planOf(const QueryCondition& condition, bool andNeedsAll, bool forParts, bool said,
                     bool nounDefaults = false) {
  said = said && condition.noun.empty();
  nounDefaults = nounDefaults || !condition.noun.empty();
  switch (condition.kind) {
    case QueryCondition::Kind::kDescriptor: {
      PrefilterPlan plan = leaf(Kind::kOverlap);
      plan.test = supportTest(condition.descriptor, condition.set);
      plan.set = condition.set;
      plan.said = said;
      plan.bySimilarity = !nounDefaults;
      plan.byExpectedMembership = nounDefaults;
      plan.relativeTo = condition.relativeTo;
      return plan;
    }
    case QueryCondition::Kind::kAnd:
    case QueryCondition::Kind::kOr: {
      std::vector<PrefilterPlan> children;
      for (const QueryCondition& child : condition.children)
        children.push_back(planOf(child, andNeedsAll, forParts, said, nounDefaults));
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

constexpr double kSlack = 1e-9;  // bounds are raised by this against rounding

double raised(double bound) { return std::min(1.0, bound + kSlack); }
// A leaf's bound of its raw score (μ, S or expected membership) as it scores: over relativeTo.
double raised(const PrefilterPlan& leaf, double bound) { return raised(bound / leaf.relativeTo); }

// Children (by id) combined: the intersection with the min of the bounds, or the union with the
// bounded sum; coverage bounds the min or the max (absentA, absentB: absentCoverage of the
// children the candidates came from, for an object one of them lacks).
std::vector<Candidate> combineCandidates(const std::vector<Candidate>& a, const std::vector<Candidate>& b, bool all,
                                         double absentA, double absentB) {
  std::vector<Candidate> out;
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].id < b[j].id)) {
      if (!all) out.push_back({a[i].id, a[i].bound, std::max(a[i].tie, absentB)});
      ++i;
    } else if (i == a.size() || b[j].id < a[i].id) {
      if (!all) out.push_back({b[j].id, b[j].bound, std::max(b[j].tie, absentA)});
      ++j;
    } else {
      out.push_back({a[i].id, all ? std::min(a[i].bound, b[j].bound) : std::min(1.0, a[i].bound + b[j].bound),
                     all ? std::min(a[i].tie, b[j].tie) : std::max(a[i].tie, b[j].tie)});
      ++i;
      ++j;
    }
  }
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

double membershipIntegral(const FuzzyNumber& set, double lo, double hi) {
  const std::vector<Breakpoint>& p = set.breakpoints();
  double area = 0;
  for (size_t k = 1; k < p.size(); ++k) {
    const double x0 = std::max(lo, p[k - 1].x), x1 = std::min(hi, p[k].x);
    if (!(x1 > x0)) continue;
    const double slope = (p[k].mu - p[k - 1].mu) / (p[k].x - p[k - 1].x);
    const double m0 = p[k - 1].mu + slope * (x0 - p[k - 1].x), m1 = p[k - 1].mu + slope * (x1 - p[k - 1].x);
    area += 0.5 * (m0 + m1) * (x1 - x0);
  }
  return area;
}

namespace {

double maxMembership(const FuzzyNumber& set, double lo, double hi) {
  double m = std::max(set.membership(lo), set.membership(hi));
  for (const Breakpoint& p : set.breakpoints())
    if (p.x >= lo && p.x <= hi) m = std::max(m, p.mu);
  return m;
}

// The bound of every wide value with support inside [lo, hi] (lo < hi), unraised: S <= |A∩B|/|B|
// <= ∫_lo^hi μ_set / |set| (1 against a crisp set); expected membership <= max μ_set there.
double wideBound(const PrefilterPlan& leaf, double lo, double hi) {
  double bound = 0;
  if (leaf.byExpectedMembership) bound = maxMembership(leaf.set, lo, hi);
  if (leaf.bySimilarity) {
    const double setArea = leaf.set.cardinality();
    bound = std::max(bound, setArea > 0 ? membershipIntegral(leaf.set, lo, hi) / setArea * (1 + kSlack) : 1.0);
  }
  return bound;
}

}  // namespace

double scoreBound(const PrefilterPlan& leaf, double supportLo, double supportHi, bool pending) {
  if (pending) return 1;
  if (supportLo == supportHi) return raised(leaf, leaf.set.membership(supportLo));
  return raised(leaf, wideBound(leaf, supportLo, supportHi));
}

double coverageBound(const PrefilterPlan& leaf, double supportLo, double supportHi, bool pending) {
  if (pending || !leaf.said) return 1;
  if (supportLo == supportHi) return leaf.set.cardinality() > 0 ? 0 : 1;
  return scoreBound(leaf, supportLo, supportHi, false);
}

double absentCoverage(const PrefilterPlan& plan) {
  if (plan.kind == Kind::kOverlap) return plan.said ? 0 : 1;
  if (plan.kind == Kind::kNone) return 0;
  if (plan.kind == Kind::kAll) return 1;
  double most = 0;
  for (const PrefilterPlan& child : plan.children) most = std::max(most, absentCoverage(child));
  return most;
}

namespace {

// How μ_set runs over [lo, hi]: through its values at the ends and every breakpoint between.
LevelOrder membershipOrder(const FuzzyNumber& set, double lo, double hi) {
  std::vector<double> mu{set.membership(lo)};
  for (const Breakpoint& p : set.breakpoints())
    if (p.x > lo && p.x < hi) mu.push_back(p.mu);
  mu.push_back(set.membership(hi));
  const bool rising = std::is_sorted(mu.begin(), mu.end());
  const bool falling = std::is_sorted(mu.rbegin(), mu.rend());
  if (rising && falling) return LevelOrder::kFlat;
  return rising ? LevelOrder::kRising : falling ? LevelOrder::kFalling : LevelOrder::kAny;
}

}  // namespace

double crispLevelBound(const PrefilterPlan& leaf, double fromLo, double toLo) {
  return raised(leaf, maxMembership(leaf.set, fromLo, toLo));
}

std::vector<LevelPiece> levelPieces(const PrefilterPlan& leaf, double maxWidth, double fromLo, double toLo) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cuts;  // each piece starts at fromLo or at a cut in (fromLo, toLo]
  for (double level : {1.0, 0.9, 0.75, 0.5, 0.25, 0.1}) {
    const Interval cut = leaf.set.alphaCut(level);
    for (double end : {cut.lo, std::nextafter(cut.hi, inf)}) {
      cuts.push_back(end);
      // Wide rows: a piece's reach is its end + maxWidth, so cuts at quarters of maxWidth before
      // each end give pieces whose reach stops short of it, and tighter bounds.
      if (maxWidth > 0)
        for (double k : {1.0, 0.75, 0.5, 0.25}) cuts.push_back(end - k * maxWidth);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<LevelPiece> pieces;
  const double setArea = leaf.set.cardinality();
  double start = fromLo;
  auto close = [&](double end) {  // the piece [start, end]
    LevelPiece piece{start, end, 1};
    if (maxWidth == 0) {
      piece.bound = crispLevelBound(leaf, start, end);
      piece.order = membershipOrder(leaf.set, start, end);
    } else if (setArea > 0 || leaf.byExpectedMembership) {
      // The widest support the piece holds ends at end + maxWidth; one ulp more against rounding
      // of support_hi - support_lo (widthClass).
      const double reach = std::nextafter(end + maxWidth * (1 + 1e-12), inf);
      piece.bound = raised(leaf, wideBound(leaf, start, reach));
    }
    pieces.push_back(piece);
  };
  for (double cut : cuts) {
    if (!(cut > start) || cut > toLo) continue;
    close(std::nextafter(cut, -inf));
    start = cut;
  }
  close(toLo);
  return pieces;
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
  return planOf(query.root, aggregationNeedsAll(query.aggregation), kind == "part", true);
}

std::vector<Candidate> runPrefilter(const PrefilterPlan& plan, const OverlapSource& overlap, const AllSource& all,
                                    bool oneRowPerObject) {
  switch (plan.kind) {
    case Kind::kAll: {
      std::vector<Candidate> out;
      for (int64_t id : all()) out.push_back({id, 1.0, 1.0});
      return out;
    }
    case Kind::kNone:
      return {};
    case Kind::kOverlap: {
      std::vector<Candidate> rows = overlap(plan);
      if (oneRowPerObject) return rows;
      // By id, one candidate per object: the largest bounds of its rows (a shape's best component).
      std::sort(rows.begin(), rows.end(), [](const Candidate& a, const Candidate& b) { return a.id < b.id; });
      std::vector<Candidate> merged;
      for (const Candidate& row : rows) {
        if (!merged.empty() && merged.back().id == row.id) {
          merged.back().bound = std::max(merged.back().bound, row.bound);
          merged.back().tie = std::max(merged.back().tie, row.tie);
        } else {
          merged.push_back(row);
        }
      }
      return merged;
    }
    case Kind::kAnd:
    case Kind::kOr: {
      const bool intersect = plan.kind == Kind::kAnd;
      std::vector<Candidate> out = runPrefilter(plan.children.front(), overlap, all);
      double absent = absentCoverage(plan.children.front());  // of the children combined so far
      for (size_t i = 1; i < plan.children.size() && !(intersect && out.empty()); ++i) {
        const double absentChild = absentCoverage(plan.children[i]);
        out = combineCandidates(out, runPrefilter(plan.children[i], overlap, all), intersect, absent, absentChild);
        absent = std::max(absent, absentChild);
      }
      return out;
    }
  }
  return {};
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
