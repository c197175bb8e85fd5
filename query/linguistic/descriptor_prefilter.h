#pragma once
// The SQL prefilter of linguistic queries (the derivation principle of SQLf): from a
// parsed query (query/linguistic/linguistic_query.h), a plan of descriptor support overlaps that every
// object scoring above 0 satisfies, so the search scores only the plan's candidates and returns
// exactly what scoring every object would (tests/server/service/linguistic_index_property_test).
//
// Rules (docs/api.md §5: S(A, B) = min(|A∩B|/|A|, |A∩B|/|B|), and μ_C(x) for a crisp value, is 0
// unless the supports of value and condition meet):
// - kDescriptor: the component value's support [slo, shi] must meet the support [lo, hi] of
//   `set` as far as S can be > 0 (geometry/fuzzy/fuzzy_similarity.h), which is sharper than touching:
//   * a crisp value x scores μ_set(x): x in [lo, hi], an end only where μ_set is > 0 there (a
//     vertical side), so a crisp 0 does not meet a set rising from 0;
//   * a wide value (slo < shi; describePart's values are convex, so it has area > 0) against a
//     set of area > 0 needs |A∩B| > 0: the interiors overlap, slo < hi and shi > lo;
//   * against a set of area 0 (a crisp set) S is the height of A∩B: slo <= hi and shi >= lo.
//   An "at least t" threshold keeps this support test (the plan only has to be a superset).
// - kAnd: every child when the aggregation is a t-norm (T(0, x) = 0: min, product, ...); any
//   child otherwise (a mean is > 0 when one child is).
// - kOr: any child (every t-conorm and max is 0 only when all children are).
// - kNot: no filter (1 − S is 1 where S is 0).
// - kRelation: for parts, nothing (a lone part scores 0 on a relation, query/linguistic/linguistic_query.h);
//   for shapes, no filter.
// Score bounds: runPrefilter gives each candidate a bound >= its score, from the supports the
// index returns, so the search can score candidates best bound first and stop once the k-th best
// exact score beats the next bound (server/service/linguistic_search.h). For a kDescriptor condition:
// a crisp value x scores μ_set(x) exactly; a wide value [slo, shi] scores at most
// |A∩B|/|B| <= ∫_slo^shi μ_set / |set| (any value against a crisp set: 1), or under a noun's
// node (expected membership) at most the largest μ_set over [slo, shi]; a pending object: 1.
// A shape takes the largest bound of its components. kAnd under a t-norm takes the children's
// min (T <= min); kOr (max or a t-conorm: <= the bounded sum) and a non-t-norm kAnd (a mean is
// <= max) take min(1, sum); kAll is 1. Each bound is raised by 1e-9 against rounding.
// The plan is simplified as it is built: kAll children of a kAnd and kNone children of a kOr
// drop out, a kNone child of a needs-all kAnd makes it kNone, a kAll child of a kOr makes it kAll.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "query/linguistic/linguistic_query.h"

namespace fsdb {

// What a component's support [slo, shi] of one descriptor must satisfy (see the rules above).
struct SupportTest {
  std::string descriptor;
  double lo = 0, hi = 0;     // the support of the condition's set
  bool loIncluded = true;    // a crisp value may equal lo (μ_set(lo) > 0)
  bool hiIncluded = true;    // a crisp value may equal hi (μ_set(hi) > 0)
  bool wideStrict = false;   // wide values need slo < hi and shi > lo (set of area > 0)
};
SupportTest supportTest(const std::string& descriptor, const FuzzyNumber& set);
// Whether a value with support [slo, shi] passes (what the store's index scan computes).
bool admits(const SupportTest& test, double slo, double shi);

struct PrefilterPlan {
  enum class Kind { kAll, kNone, kOverlap, kAnd, kOr };
  Kind kind = Kind::kAll;
  SupportTest test;                     // kOverlap
  FuzzyNumber set;                      // kOverlap: the condition's set (for score bounds)
  // kOverlap: the words say it of the part itself, so QueryScore::coverage reads it (not a noun's
  // default: saysVagueness, query/linguistic/linguistic_query.h).
  bool said = false;
  // kOverlap: how the leaf is scored. A noun's default scores its expected membership, at most
  // the largest μ_set over the value's support (geometry/fuzzy/fuzzy_similarity.h); anything else
  // S. A leaf said both ways (two merged leaves) is bounded for both.
  bool bySimilarity = true;
  bool byExpectedMembership = false;
  // kOverlap: QueryCondition::relativeTo (the score is min(1, s / relativeTo)), so every bound is
  // divided by it; two merged leaves keep the smaller.
  double relativeTo = 1.0;
  std::vector<PrefilterPlan> children;  // kAnd, kOr: two or more
};

// A candidate, a bound >= its score and a bound >= its coverage (QueryScore::coverage, which
// breaks ties of score). Coverage bounds: a said kOverlap leaf's is 0 for a crisp row against a
// set of area > 0 (a point spans nothing of it), scoreBound for a wide row (which bounds
// |A∩B|/|B|), 1 for a pending object and for a leaf that is not said. A kAnd takes the
// children's least, a kOr their largest, where an object missing from a child takes absentCoverage
// of it; a shape the largest of its components; kAll 1.
struct Candidate {
  int64_t id = 0;
  double bound = 1;
  double tie = 1;
};
double coverageBound(const PrefilterPlan& leaf, double supportLo, double supportHi, bool pending);
// The coverage bound of an object that fails the support tests of `plan`: 0 when every leaf under
// it is said (the failing leaf scores 0, so spans nothing of its set: coverage 0), else 1.
double absentCoverage(const PrefilterPlan& plan);

// The bound of one kOverlap leaf for a component row with support [supportLo, supportHi] found
// by the index, or for a pending object (see above).
double scoreBound(const PrefilterPlan& leaf, double supportLo, double supportHi, bool pending);
// ∫_lo^hi μ(x) dx, exact for the piecewise-linear membership.
double membershipIntegral(const FuzzyNumber& set, double lo, double hi);

// The level scan (server/service/linguistic_search.h): the rows of one index range of a kOverlap leaf,
// support_lo in [fromLo, toLo] and widths <= maxWidth (0: crisp rows), cut into pieces at the
// ends of the alpha-cuts of leaf.set (levels 1, 0.9, 0.75, 0.5, 0.25, 0.1; for wide rows also
// those ends minus 1, 3/4, 1/2 and 1/4 of maxWidth), each with a bound >= the score of every row in it, so the search
// can read the best pieces first and stop before the rest. The pieces cover [fromLo, toLo]
// exactly (adjacent, disjoint, in order). Bounds (the rules above, over all the rows a piece can
// hold): a crisp x in [s0, s1] scores μ_set(x) <= max of μ_set over [s0, s1] (at s0, s1 or a
// breakpoint between: μ_set is piecewise linear); a wide value has support in
// [s0, s1 + maxWidth], so S <= |A∩B|/|B| <= ∫_s0^(s1+maxWidth) μ_set / |set| (1 for a crisp set),
// and a noun's default (expected membership) <= the largest μ_set over [s0, s1 + maxWidth].
// Raised like scoreBound, and never below scoreBound of a row the piece holds.
// order (crisp pieces only, else kAny): how μ_set runs over [fromLo, toLo], so the search can read
// the rows best first and stop early: kRising (non-decreasing: best at the top, read by value
// descending), kFalling (read ascending), kFlat (constant: every row has the piece's bound and
// ties go by id, so read in id order).
enum class LevelOrder { kAny, kRising, kFalling, kFlat };
struct LevelPiece {
  double fromLo = 0, toLo = 0;
  double bound = 1;
  LevelOrder order = LevelOrder::kAny;
};
std::vector<LevelPiece> levelPieces(const PrefilterPlan& leaf, double maxWidth, double fromLo, double toLo);
// The bound of every crisp row with value in [fromLo, toLo]: the largest μ_set there, raised.
double crispLevelBound(const PrefilterPlan& leaf, double fromLo, double toLo);

// Whether kAnd under this aggregation is 0 as soon as one child is (a t-norm).
bool aggregationNeedsAll(const std::string& aggregation);

// The plan for objects of `kind` ("part" or "shape").
PrefilterPlan prefilterPlan(const LinguisticQuery& query, const std::string& kind);

// The candidates of `plan` by id, with bounds: kOverlap through `overlap(leaf)` (one candidate
// per row the index finds for leaf.test, in any order, bounded with scoreBound; the rows of one
// object merge into its largest bound), kAll through `all()` (sorted ids, bound 1), kAnd as the
// intersection, kOr as the union. oneRowPerObject (parts: one component): a plan that is one
// kOverlap returns the source's rows as they come, unsorted (the search orders by bound anyway).
using OverlapSource = std::function<std::vector<Candidate>(const PrefilterPlan& leaf)>;
using AllSource = std::function<std::vector<int64_t>()>;
std::vector<Candidate> runPrefilter(const PrefilterPlan& plan, const OverlapSource& overlap, const AllSource& all,
                                    bool oneRowPerObject = false);

// {"all":true} | {"none":true} | {"overlap":{"descriptor","lo","hi","lo_included","hi_included",
// "wide_strict"}} | {"and":[...]} | {"or":[...]}
nlohmann::json prefilterPlanJson(const PrefilterPlan& plan);

}  // namespace fsdb
