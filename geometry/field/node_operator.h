#pragma once
// NodeOperator: how a CSG node with a fuzzy_operator or blend of the catalogue
// (geometry/operators/operator_catalog.h; docs/api.md §2 "operator"; Li & Tian; Li) combines the
// alpha fields (geometry/field/alpha_field.h) of its children.
//
// Possibility and necessity. For any alpha field, u(p) is exactly the POSSIBILITY that p is
// inside, Π = u (the sup of α with p ∈ upper(α)), and 1 − l(p) the NECESSITY, N = 1 − l
// (p ∈ lower(α) ⇔ α ≥ l); l = kNeverInside gives N = 0. docs/api.md §3's lower(α) ⊆ upper(α) for
// every α says, per point, l <= 1 ⇒ u = 1, i.e.
//   N > 0 ⇒ Π = 1      (the normal-distribution axiom; it implies N <= Π)
// (every point is either only possibly inside, Π < 1 and N = 0, or possible to degree 1 and
// necessary to degree N). Every source of fsdb keeps it (fuzzy_part_field.h seeks l only where
// u = 1; membership_field.h's map from memberships), and alpha_field.h's Booleans preserve it.
// A node with t-norm T (dual conorm S) combines these pairs as fuzzy sets:
//   intersection  Π' = T(ΠA, ΠB),      N' = T(NA, NB)
//   union         Π' = S(ΠA, ΠB),      N' = S(NA, NB)
//   difference    Π' = T(ΠA, 1 − NB),  N' = T(NA, 1 − ΠB)      (A − B)
// and converts back: u = Π', l = 1 − N' where N' > 0, else kNeverInside. With T = min this is
// exactly alpha_field.h's Booleans, except on the single level α = 1: a point that Zadeh puts in
// lower(1) only (l = 1, N = 0) becomes kNeverInside here (measure zero in α; volumes at α < 1
// are unaffected). The conversions are exact in double precision (1 − l of a float is exact); for
// other operators u is rounded down and l up (so u = 1 only where Π' = 1).
//
// The axiom carries over for EVERY operator below, blends and the non-monotone ones included,
// because each gets the t-norm's boundary values (below): intersection N' > 0 needs NA, NB > 0
// (T(0, x) = 0), so ΠA = ΠB = 1 and Π' = T(1, 1) = 1; union N' > 0 needs NA > 0 or NB > 0
// (S(0, 0) = 0), so ΠA = 1 or ΠB = 1 and Π' = S(1, x) = 1; difference N' > 0 needs NA > 0 and
// ΠB < 1, so ΠA = 1 and NB = 0 and Π' = T(1, 1 − 0) = 1. These values are exact (no rounding),
// so the float levels keep it too. levelsFromPossibility enforces it all the same (N' = 0 where
// Π' < 1: lower(α) can only shrink, the conservative direction), so a child that broke it could
// not make a node report lower(α) ⊄ upper(α).
//
// Memberships. combine(op, x, y) on plain memberships in [0, 1] is the same operator: crisp parts
// smoothed to memberships μ (Li & Tian, §2.1) are combined on μ itself, and their result converts
// to a pair only where it meets the (Π, N) world (geometry/field/membership_field.h).
//
// Blends (kind "blend": ext_max, int_max) act on real fields, inside where f ≥ 0. The node
// applies them to f = x − 1/2 for each membership x (μ, or Π and N; the 0.5 level is the shape,
// Li & Tian, §2.1) and maps back with clamp(r + 1/2, 0, 1). Their delta and epsilon are therefore
// in MEMBERSHIP units (|f| ≤ 1/2): ext_max's defaults (delta 0.5, epsilon 0.25) blend almost
// everywhere; delta ≈ 0.1 keeps the blend near the crease.
//
// Boundary values. Every operator, blends included, gets the t-norm's values at 0 and 1:
// T(0, x) = 0, T(1, 1) = 1, S(1, x) = 1, S(0, 0) = 0 (so difference is 0 where ΠA = 0 or
// NB = 1, and 1 where ΠA = 1 and NB = 0). Every t-norm satisfies these already; a blend does not
// (Ext_max(x, x) = x + delta/4 would give every point of space, far from both operands,
// membership delta/4), and without them the node's support would not stay inside its
// children's (the bounding box contract of csg_field.h). They patch exact 0 and 1 only: where
// both memberships are small but positive Ext_max still adds up to delta/4, so upper(α) for
// small α (α < delta/4 on pairs, α < delta/2 on memberships: membership_field.h) fills the
// children's supports (grown boxes of smoothed parts).
//
// Monotonicity. Every t-norm of the catalogue is non-decreasing in each argument (difference
// non-increasing in B). smooth_and_hat, ext_max and int_max are not (measured dips of 5e-4, 2e-5
// and 4e-4 over [0,1]²; tests/geometry/field/node_operator_test); that only costs them block pruning.
//
// Bounds (block pruning). For a monotone operator the bounds are its values at the corners of
// the children's bounds, widened by 1e-9 where they lie strictly inside (0, 1) (rounding dips of
// 2e-16 measured for dubois_prade and smooth_and). For the others a bound is exact only where
// the boundary values fix it over the whole box (e.g. a union of two children that are empty
// there), else [0, 1]: such nodes are evaluated voxel by voxel inside their children's support.
// The same bounds serve memberships (combine on MembershipRange) and pairs; the enforcement of
// the axiom is monotone in (Π', N'), so the bounds of its result are its values at their ends.
#include <memory>

#include "geometry/field/alpha_field.h"
#include "geometry/field/csg_field.h"
#include "geometry/operators/operator_catalog.h"

namespace fsdb {

// Π = u and N = 1 − l (0 for kNeverInside) of a point, and back (see above): u rounded down, l
// up, and l = kNeverInside unless N > 0 and Π >= 1 (the axiom enforced).
double possibilityOf(AlphaLevels v);
double necessityOf(AlphaLevels v);
AlphaLevels levelsFromPossibility(double possibility, double necessity);

// A closed interval of memberships (or of Π, or of N) in [0, 1].
struct MembershipRange {
  double lo = 0.0, hi = 1.0;
};

class NodeOperator {
 public:
  // Validates (makeBinaryOperator: fsdb::Error with path "name" or the parameter's name); the
  // kind must be fuzzy_operator or blend.
  explicit NodeOperator(const OperatorConfig& config);

  // On memberships in [0, 1], with the boundary values above; difference(a, b) = T(a, 1 − b).
  double combine(CsgOp op, double a, double b) const;
  // On the levels of two children (the pair rules above).
  AlphaLevels combine(CsgOp op, AlphaLevels a, AlphaLevels b) const;
  // Sound bounds of combine over boxes where the children's levels lie within a and b.
  AlphaLevelBounds combine(CsgOp op, const AlphaLevelBounds& a, const AlphaLevelBounds& b) const;
  // Sound bounds of combine(op, x, y) over x in a, y in b (memberships).
  MembershipRange combine(CsgOp op, MembershipRange a, MembershipRange b) const;

  const OperatorConfig& config() const { return config_; }
  bool monotone() const { return monotone_; }

 private:
  OperatorConfig config_;
  std::shared_ptr<const BinaryOperator> op_;
  bool monotone_;
};

}  // namespace fsdb
