#pragma once
// FuzzyPartField: the alpha field (alpha_field.h) of one fuzzy superquadric part: upper(α) =
// ∪ S(θ) and lower(α) = ∩ S(θ) over the θ of P(α), the box of the part's α-cuts (Zhang, Pham &
// Chen §3.2; docs/api.md §3).
//
// Contract:
//  * levelsAt(p) returns (u, l) with u in [u_true − τ, u_true] and l in [l_true, l_true + τ]
//    (τ = tolerance), u rounded down and l up to floats; u carries a crisp witness θ ∈ P(u) and
//    l = 0 only where p ∈ lower(0) is proven. l <= 1 only where u = 1.
//  * A query has a budget of enclosure evaluations. When it runs out the answer is the
//    conservative one (upper can only grow, lower only shrink) and budgetExhaustions() counts it.
//  * boundsOver(lo, hi) bounds the levels of every point of the box; levelsAt answers lie within
//    them unless a point query ran out of budget. boundingBox() is a sound box around upper(0),
//    computed on first use: the forward maps' box (superquadric_extent.h), cut down to the cells
//    boundsOver cannot exclude (a few ms).
//  * u = 1 exactly where P(1) was shown to put p inside, or where that decision ran out of
//    budget (counted, conservative): within τ of 1, or on an exhausted search, P(1) is asked.
//  * possiblyInside / necessarilyInside decide one level by branch and bound (same budget).
//  * Thread-safe: queries only read the part; the exhaustion counter is atomic.
// How: a certified max-min branch and bound over the parameter box (fuzzy_part_search.cpp), with
// closed forms first where F is monotone in every fuzzy value or one size is the only fuzzy value
// (fuzzy_part_monotone.cpp); docs/design/fuzzy-part-field.md explains both and their proofs.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>

#include "geometry/numeric/affine_form.h"
#include "geometry/field/alpha_field.h"
#include "geometry/superquadric/fuzzy_part.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric_bounds.h"
#include "geometry/superquadric/superquadric_slopes.h"
#include "geometry/superquadric/transform.h"

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
  // Per block: bounds 4³ and then 2³ sub-blocks (boundsOver, then provenOverBlock where that is
  // not uniform) and fills the uniform ones, so that
  // only voxels near the fuzzy band (or the crisp surface) are evaluated one by one; crisp parts
  // evaluate F there without the virtual call; a part with one fuzzy size (sizeLevels) answers a
  // non-uniform 4³ sub-block voxel by voxel. Same values as levelsAt (up to budget exhaustion,
  // as for the grid's own block pruning).
  void sampleBlock(const BlockLattice& b, AlphaLevels* out) const override;
  // The block proof sampleBlock runs where boundsOver is not uniform (fuzzy_part_block.cpp): true
  // when a branch and bound over P(0) with at most `budget` enclosure evaluations shows that no θ
  // of P(0) puts any point of x × y × z inside (outside: the box is outside upper(0), u = 0 and
  // l = never there), or that every θ puts every point inside (!outside: the box is in lower(0),
  // u = 1 and l = 0). False when it cannot within the budget, or a crisp θ refutes the claim at
  // the box's centre.
  bool provenOverBlock(const Interval& x, const Interval& y, const Interval& z, bool outside,
                       int budget) const;

  // The branch-and-bound predicates at one level α in [0, 1]: ∃θ ∈ P(α) with F(p; θ) <= 1, and
  // ∀θ ∈ P(α) F(p; θ) <= 1. Conservative on budget exhaustion (possibly: true, necessarily: false).
  bool possiblyInside(const Vec3& p, double alpha) const;
  bool necessarilyInside(const Vec3& p, double alpha) const;

  const FuzzyPart& part() const { return part_; }
  // Every value crisp: the field is the part's indicator, (1, 0) inside and (0, never) outside.
  bool isCrisp() const { return crisp_.has_value(); }
  double tolerance() const { return options_.tolerance; }
  // How many queries ran out of budget and answered conservatively, since construction.
  std::uint64_t budgetExhaustions() const override { return exhaustions_.load(); }

 private:
  enum class Question { kPossibly, kNecessarily };
  bool decide(const Vec3& p, const PartBox& box, Question q) const;
  // One max-min search (docs/design/fuzzy-part-field.md): incumbent = the best m(θ) of a witness (-1: none), witness
  // its θ; pruned = the largest bound of a box dropped without a witness (-1: none) or, when
  // exhausted, of the boxes still open.
  struct Search {
    double incumbent = -1.0;
    double pruned = -1.0;
    bool exhausted = false;
    PlacedSuperquadric witness;
  };
  // A witness the search may start from: θ qualifies (F <= 1 for u, F > 1 for l) and lies in
  // P(level). level < 0: none.
  struct Seed {
    double level = -1.0;
    PlacedSuperquadric witness;
  };
  Search maxMin(const Vec3& p, bool inside, const Seed& seed) const;
  class MaxMinSearch;  // one maxMin call's state and steps (fuzzy_part_search.cpp)
  // Is the box excluded for the search (inside: no θ with F <= 1; else none with F > 1) once its
  // monotone values are collapsed to their ends? Adds its evaluations to *evaluations.
  // slopes holds ∂F/∂θ for the `count` slots `open` over a box that holds `box` (the caller's,
  // taken by the first round; the later rounds compute their own over the collapsed box).
  bool collapsedExcludes(const PartBox& box, const Vec3& p, bool inside, int* evaluations,
                         const int* open, int count, const Interval* slopes) const;
  // Dominance narrowing (fuzzy_part_search.cpp): narrows the box to the θ that no other θ of it beats, for
  // slopes d of the `count` slots `open` over the box; true when the box changed.
  bool narrowByDominance(PartBox* box, const int* open, int count, const Interval* d,
                         bool inside) const;
  // The linearised bound (fuzzy_part_search.cpp) of the qualifying θ of `box`, from the affine form of F
  // over formBox (which holds box); <= ub, or −1 when no θ of box can qualify.
  double linearizedBound(const PartBox& box, const PartBox& formBox, const AffineForm& form,
                         bool inside, double ub) const;
  PartBox cutAt(double alpha) const;  // boxAt(alpha), cutting only the fuzzy values
  // Monotone shortcut (fuzzy_part_monotone.cpp): sign[i] = +1 / −1 when F is nondecreasing / nonincreasing in
  // fuzzy value i over the point box [lo, hi] × P(0) (0 for crisp values); false unless every
  // fuzzy value has a sign.
  bool monotoneSigns(const Vec3& lo, const Vec3& hi, signed char* sign) const;
  // The same over the point box × `box` (a cut P(α) instead of P(0)).
  bool monotoneSignsOver(const PartBox& box, const Vec3& lo, const Vec3& hi,
                         signed char* sign) const;
  // The monotone shortcut above a level (fuzzy_part_monotone.cpp): the corner path with the core's
  // signs, its brackets proven by the signs over the cut at their upper ends. 0: u not answered;
  // 1: u = 1 answered in *out, l not; 2: both answered.
  // Where it cannot answer, *up and *down hold the witnesses its brackets found (their lower
  // ends), for the searches to start from.
  int levelsAboveCut(const Vec3& p, AlphaLevels* out, Seed* up, Seed* down) const;
  // levelsAt where monotoneSigns holds over a box that contains p; inCore: p is known to be
  // inside S(θ) for every θ of P(1) (then u = 1 needs no evaluation).
  AlphaLevels cornerLevels(const Vec3& p, const signed char* sign, bool inCore = false) const;
  // levelsAt in closed form for one fuzzy size of an undeformed part (sizeSlot_ >= 0;
  // fuzzy_part_monotone.cpp); false where its checks disagree (then the general path answers).
  bool sizeLevels(const Vec3& p, AlphaLevels* out) const;
  // The corner of P(alpha) where F is least (least) or largest, for the given signs.
  PlacedSuperquadric cornerAt(double alpha, const signed char* sign, bool least) const;
  // u rounded down to a float whose cut still holds the witness (p ∈ upper(u) stays shown).
  float roundedUpper(double u, const PlacedSuperquadric& witness) const;
  // The box of deformation and placement bounds over the support box (sound, often loose).
  void looseBoundingBox(Vec3* lo, Vec3* hi) const;
  // boxLo_, boxHi_: the loose box ∩ the forward maps' box, with the cells boundsOver proves
  // outside upper(0) cut away.
  void tightenBoundingBox() const;
  PartBox levelBox(double alpha) const;  // P(alpha), the stored support and core at 0 and 1
  double valueAt(const PlacedSuperquadric& theta, const Vec3& p) const;  // F(p; θ)
  // Signs of monotoneSigns over a whole block, computed when first needed.
  struct BlockSigns {
    int state = 0;  // 0 not computed, 1 monotone over the block, 2 not
    signed char sign[kPartSlots];
  };
  // sampleBlock over the sub-block of `size`³ voxels at (i, j, k) of the block.
  void sampleSubBlock(const BlockLattice& b, int i, int j, int k, int size, BlockSigns* signs,
                      AlphaLevels* out) const;

  FuzzyPart part_;
  FuzzyPartFieldOptions options_;
  PartBox support_;          // P(0)
  PartBox core_;             // P(1)
  PartBox coreMidpoint_;     // the one θ at the middle of P(1) (levelsAboveCut's guess)
  double supportWidth_[kPartSlots];  // widths of P(0), the yardstick for choosing a split
  const FuzzyNumber* values_[kPartSlots];  // the part's values, in slot order
  int fuzzySlots_[kPartSlots];            // the slots of the fuzzy values, fuzzyCount_ of them
  int fuzzyCount_ = 0;
  bool crispAngle_ = false;        // deg crisp: one rotation for every θ
  Rotation rotation_;
  // Set when every value is crisp: then P(α) is one θ for every α, upper(α) = lower(α) = S(θ),
  // and levelsAt is one crisp evaluation (u, l) = (1, 0) inside, (0, never) outside.
  std::optional<PreparedSuperquadric> crisp_;
  // Set (the slot: 2 a1 or 13 scale) when that is the only fuzzy value and the part has no taper,
  // twist or bend: then F(p; v) = (ρ(p)/v)^(2/ε1) and sizeLevels answers in closed form.
  int sizeSlot_ = -1;
  double sizeReference_ = 1.0;              // v_ref, the core's midpoint
  PlacedSuperquadric sizeReferencePart_;    // the part at v_ref
  mutable std::atomic<std::uint64_t> exhaustions_{0};
  mutable std::once_flag boxOnce_;  // boundingBox(): tightenBoundingBox on first use
  mutable Vec3 boxLo_, boxHi_;
};

namespace reference {
// The previous levelsAt, kept as the reference for tests: bisection in α on dyadic brackets, one
// possiblyInside / necessarilyInside decision per bracket (same guarantees, much slower).
AlphaLevels bisectionLevelsAt(const FuzzyPartField& field, const Vec3& p);
}  // namespace reference

}  // namespace fsdb
