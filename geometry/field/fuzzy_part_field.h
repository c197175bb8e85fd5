#pragma once
// FuzzyPartField: the alpha field (alpha_field.h) of one fuzzy superquadric part (fsdb issue 3;
// docs/api.md §3, Zhang, Pham & Chen, §3.2): upper(α) = ∪ S(θ) and lower(α) = ∩ S(θ) over θ in P(α).
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
// levelsAt(p) solves two max-min problems over the parameters instead of bisecting α. With
// m(θ) = min_i μ̂_i(θ_i) over the fourteen values (μ̂: the quasi-concave envelope of a membership,
// whose cuts are the hulls boxAt uses, so θ ∈ P(α) ⇔ m(θ) >= α for α > 0):
//   u(p) = sup{m(θ) : θ ∈ P(0), F(p; θ) <= 1}   (p ∈ upper(α) ⇔ some θ with m(θ) >= α has F <= 1)
//   l(p) = sup{m(θ) : θ ∈ P(0), F(p; θ) > 1}    (p ∉ lower(α) ⇔ some θ with m(θ) >= α has F > 1;
//          l = 0 when no θ of P(0) has F > 1, kNeverInside when one of P(1) has)
// Each is a best-first branch and bound over sub-boxes of P(0): a box's bound is min_i of the
// largest μ̂_i over its interval (exact for piecewise-linear memberships, plus 1e-12); it is
// dropped when the enclosure excludes it (lo > 1 for u, hi <= 1 for l) or when its bound does not
// beat the incumbent (the best crisp witness) by more than τ; once there is an incumbent every
// box is cut to P(incumbent + τ) before its enclosure is taken (the levels reuse one another's
// work). Witnesses come from the box's peak (each value clamped to its core: a witness there
// settles the box), the corner that F's slopes favour (central differences at the core midpoint,
// and after each new incumbent at its witness), or the centre, then a regula
// falsi walk towards the peak; boxes are split where fixing a value to its midpoint moved the
// enclosure most (measured at the first box, and again every as many splits deep as there are
// fuzzy values). Until the first witness, and for at most a
// quarter of the budget, the search dives (the box whose centre is nearest a witness first; then
// best first, so that an exhausted search's largest open bound has come down). For u the search starts cut to P(τ): u = 0 is a correct
// answer for any u_true <= τ. A fast exit first tries the enclosure over P(0) at p. Two more
// sound exclusions: a box whose placement cannot bring p into the local box that holds every
// S(θ) of it (missesDeformedHull) has no θ with F <= 1, and a box is dropped when the box with
// its monotone values collapsed to their F-lowering (u) or F-raising (l) ends is excluded by its
// enclosure or mean value form (a θ qualifies in the box only if one does in the collapsed box),
// and, before that, a signed value's half of the box beyond its core on the side where moving
// towards the core helps (lower F for u, higher for l) is cut away (narrowByDominance: the moved
// θ has at least the same m, so the best m stays in the box);
// before each collapse the box is also tried with the mean value form about Baumann's centre
// (meanValueEnd, superquadric_slopes.h), from the same slopes and one crisp evaluation.
// The searches' enclosure of a box is the interval one intersected with the affine one
// (superquadric_affine.h: one noise symbol per value, a second-order remainder), and each box is
// first narrowed by affine contraction to the θ that can still qualify (F <= 1 for u, F > 1 for
// l; every such θ stays in it); the same form's linear condition also lowers the box's bound to
// the highest level whose cut of the box still meets it (linearizedBound: the values traded
// against one another, where the box bound takes each at its best).
//  * u: the incumbent, rounded down and checked: its witness lies in P(u) (so u = 1 only when p ∈
//    upper(1) was shown). u lies in [u_true − τ, u_true] unless the budget ran out; then u is the
//    largest bound still open (an upper bound of u_true: upper grows).
//  * l: the largest bound of what was dropped without a witness, or the incumbent, rounded up: l
//    lies in [l_true, l_true + τ]; l = 0 only where every box was excluded (p ∈ lower(0) proven),
//    otherwise l >= τ. When that bound reaches 1, l = 1 if necessarilyInside(p, 1) else
//    kNeverInside. A budget exhaustion gives the largest bound still open (l can only rise). l is
//    sought only where u = 1, so l <= 1 implies u = 1 in the output. Floats keep the rounding
//    directions (u down, l up).
// Monotone shortcut, tried first: where the interval slopes (superquadric_slopes.h) of F over
// P(0) at p give every fuzzy value a sign, F is monotone in each, so min / max of F over P(α) are
// F at two corners of P(α) that move with α, exactly; u and l are then brackets of width τ on
// those two functions of α (secant steps, a few crisp evaluations, no budget), with the same
// guarantees and rounding as below. sampleBlock tries the slopes over the whole block first and
// uses them for all its voxels. Parts with a few fuzzy size, scale, exponent or translation
// values take it almost everywhere; with many fuzzy deformation values the slopes over P(0)
// rarely all have a sign and the search below runs.
// Each of the two searches is one query with the evaluation budget (the split weights' enclosures
// count). reference::bisectionLevelsAt keeps the previous bisection (tests compare the two).
//
// boundsOver(lo, hi) bounds the true levels of every point of the box, from missesDeformedHull and
// the enclosure over the point box with P(0) and P(1) (decisions keep a relative margin of 1e-12 from 1, for the unrounded
// enclosure). levelsAt answers lie within them unless a point query ran out of budget: the
// enclosure is not monotone under inclusion, so a block may be excluded whole while one of its
// points needs splitting. boundingBox() is a simple sound box around upper(0) (deformation and
// placement bounds over the support box).
//
// Thread-safe: queries only read the part; the exhaustion counter is atomic.
#include <atomic>
#include <cstdint>
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
  // Per block: bounds 4³ and then 2³ sub-blocks (boundsOver) and fills the uniform ones, so that
  // only voxels near the fuzzy band (or the crisp surface) are evaluated one by one; crisp parts
  // evaluate F there without the virtual call; a part with one fuzzy size (sizeLevels) answers a
  // non-uniform 4³ sub-block voxel by voxel. Same values as levelsAt (up to budget exhaustion,
  // as for the grid's own block pruning).
  void sampleBlock(const BlockLattice& b, AlphaLevels* out) const override;

  // The branch-and-bound predicates at one level α in [0, 1] (see above).
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
  // One max-min search (see levelsAt): incumbent = the best m(θ) of a witness (-1: none), witness
  // its θ; pruned = the largest bound of a box dropped without a witness (-1: none) or, when
  // exhausted, of the boxes still open.
  struct Search {
    double incumbent = -1.0;
    double pruned = -1.0;
    bool exhausted = false;
    PlacedSuperquadric witness;
  };
  Search maxMin(const Vec3& p, bool inside) const;
  // Is the box excluded for the search (inside: no θ with F <= 1; else none with F > 1) once its
  // monotone values are collapsed to their ends? Adds its evaluations to *evaluations.
  // slopes holds ∂F/∂θ for the `count` slots `open` over a box that holds `box` (the caller's,
  // taken by the first round; the later rounds compute their own over the collapsed box).
  bool collapsedExcludes(const PartBox& box, const Vec3& p, bool inside, int* evaluations,
                         const int* open, int count, const Interval* slopes) const;
  // Dominance narrowing (see the .cpp): narrows the box to the θ that no other θ of it beats, for
  // slopes d of the `count` slots `open` over the box; true when the box changed.
  bool narrowByDominance(PartBox* box, const int* open, int count, const Interval* d,
                         bool inside) const;
  // The linearised bound (see the .cpp) of the qualifying θ of `box`, from the affine form of F
  // over formBox (which holds box); <= ub, or −1 when no θ of box can qualify.
  double linearizedBound(const PartBox& box, const PartBox& formBox, const AffineForm& form,
                         bool inside, double ub) const;
  PartBox cutAt(double alpha) const;  // boxAt(alpha), cutting only the fuzzy values
  // Monotone shortcut (see above): sign[i] = +1 / −1 when F is nondecreasing / nonincreasing in
  // fuzzy value i over the point box [lo, hi] × P(0) (0 for crisp values); false unless every
  // fuzzy value has a sign.
  bool monotoneSigns(const Vec3& lo, const Vec3& hi, signed char* sign) const;
  // levelsAt where monotoneSigns holds over a box that contains p; inCore: p is known to be
  // inside S(θ) for every θ of P(1) (then u = 1 needs no evaluation).
  AlphaLevels cornerLevels(const Vec3& p, const signed char* sign, bool inCore = false) const;
  // levelsAt in closed form for one fuzzy size of an undeformed part (sizeSlot_ >= 0; see the
  // .cpp); false where its checks disagree (then the general path answers).
  bool sizeLevels(const Vec3& p, AlphaLevels* out) const;
  // The corner of P(alpha) where F is least (least) or largest, for the given signs.
  PlacedSuperquadric cornerAt(double alpha, const signed char* sign, bool least) const;
  // u rounded down to a float whose cut still holds the witness (p ∈ upper(u) stays shown).
  float roundedUpper(double u, const PlacedSuperquadric& witness) const;
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
};

namespace reference {
// The previous levelsAt, kept as the reference for tests: bisection in α on dyadic brackets, one
// possiblyInside / necessarilyInside decision per bracket (same guarantees, much slower).
AlphaLevels bisectionLevelsAt(const FuzzyPartField& field, const Vec3& p);
}  // namespace reference

}  // namespace fsdb
