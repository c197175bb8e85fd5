#pragma once
// FuzzyPartField: the alpha field (alpha_field.h) of one fuzzy superquadric part (fsdb issue 3;
// SPEC §3, seed 004 §3.2): upper(α) = ∪ S(θ) and lower(α) = ∩ S(θ) over θ in P(α).
//
// Point queries are certified branch and bound over the parameter box at the point:
//  * possiblyInside(p, α)  ⇔ ∃θ ∈ P(α): F(p; θ) <= 1. "false" needs the interval enclosure
//    (superquadric_bounds.h) of every sub-box to exceed 1; "true" needs a crisp witness θ.
//  * necessarilyInside(p, α) ⇔ ∀θ ∈ P(α): F(p; θ) <= 1. "true" needs every sub-box's enclosure <=
//    1; "false" needs a crisp witness θ with F > 1. Undecided boxes are split across their widest
//    value, measured relative to that value's support width. A query has a budget of enclosure
//    evaluations; when it runs out the answer is the conservative one for the set it serves and
//    budgetExhaustions() counts it: possiblyInside answers true (upper is an outer bound),
//    necessarilyInside false (lower is an inner bound). So the computed upper(α) can only grow and
//    lower(α) only shrink. Exhaustion happens near the level where p crosses a boundary (the
//    cluster effect of first-order enclosures: the margin to 1 vanishes there) and where the
//    enclosure is loose (many fuzzy values, taper factors near 0).
//
// levelsAt(p) bisects α on dyadic brackets down to the tolerance τ (default 1/1024):
//  * u: the bracket end where p was shown possibly inside (rounded down, so u = 1 only when p ∈
//    upper(1) was shown); u lies in [u_true − τ, u_true] unless the budget ran out (then it may be
//    higher).
//  * l: the bracket end where p was shown necessarily inside (rounded up, so l = 0 only when p ∈
//    lower(0) was proven); l lies in [l_true, l_true + τ], or is kNeverInside; a budget exhaustion
//    can only raise it. l is sought only where u = 1 (p ∈ lower(1) ⊆ upper(1)), so l <= 1 implies u
//    = 1 in the output: lower ⊆ core ⊆ upper holds even where rounding could make the predicates
//    disagree. Floats keep the rounding directions (u down, l up).
//
// boundsOver(lo, hi) bounds the true levels of every point of the box, from the enclosure over the
// point box with P(0) and P(1) (decisions keep a relative margin of 1e-12 from 1, for the unrounded
// enclosure). levelsAt answers lie within them unless a point query ran out of budget: the
// enclosure is not monotone under inclusion, so a block may be excluded whole while one of its
// points needs splitting. boundingBox() is a simple sound box around upper(0) (deformation and
// placement bounds over the support box).
//
// Thread-safe: queries only read the part; the exhaustion counter is atomic.
#include <atomic>
#include <cstdint>

#include "geometry/alpha_field.h"
#include "geometry/fuzzy_part.h"
#include "geometry/superquadric_bounds.h"

namespace fsdb {

struct FuzzyPartFieldOptions {
  // Bisection tolerance in α: (0, 0.5]. 1/1024 is below the resolution anyone reads from a level
  // set (ten bisection steps) and makes every bracket end a dyadic float.
  double tolerance = 1.0 / 1024.0;
  // Enclosure evaluations per branch-and-bound query, >= 1.
  int evaluationBudget = 4096;
};

class FuzzyPartField : public AlphaFieldSource {
 public:
  // Validates the part (FuzzyPart::validate) and the options (paths "tolerance",
  // "evaluationBudget"); throws fsdb::Error(errc::kInvalidParameter).
  explicit FuzzyPartField(const FuzzyPart& part, FuzzyPartFieldOptions options = {});

  AlphaLevels levelsAt(const Vec3& p) const override;
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;

  // The branch-and-bound predicates at one level α in [0, 1] (see above).
  bool possiblyInside(const Vec3& p, double alpha) const;
  bool necessarilyInside(const Vec3& p, double alpha) const;

  const FuzzyPart& part() const { return part_; }
  double tolerance() const { return options_.tolerance; }
  // How many queries ran out of budget and answered conservatively, since construction.
  std::uint64_t budgetExhaustions() const { return exhaustions_.load(); }

 private:
  enum class Question { kPossibly, kNecessarily };
  bool decide(const Vec3& p, const PartBox& box, Question q) const;

  FuzzyPart part_;
  FuzzyPartFieldOptions options_;
  PartBox support_;          // P(0)
  PartBox core_;             // P(1)
  double supportWidth_[14];  // widths of P(0), the yardstick for choosing a split
  mutable std::atomic<std::uint64_t> exhaustions_{0};
};

}  // namespace fsdb
