#pragma once
// Smooth CSG nodes: a CSG node whose operator is a fuzzy set operator or a blend of the catalogue
// instead of Zadeh's min/max (docs/api.md §2 "operator"; Li & Tian; Li). The operator algebra, the
// blends on x − 1/2 and the bounds are geometry/field/node_operator.h's; crisp parts become graded
// solids μ(F(P)) (Li & Tian, §2.1; geometry/field/smoothed_part_field.h), which are memberships
// (geometry/field/membership_field.h). A node lives in one of two worlds:
//   MembershipCsgField: every child is a membership (a smoothed crisp part, or a node of them).
//     The node combines the memberships themselves, μ' = T(μA, μB) (S for union, T(μA, 1 − μB)
//     for difference) exactly as Li & Tian blend implicit shapes, and μ' is again a membership:
//     its 0.5 level is the blended surface, and as an alpha field (membership_field.h) its core
//     (α = 1) is that blended shape, upper(α) = {μ' ≥ α/2} grows and lower(α) = {μ' ≥ 1 − α/2}
//     shrinks as α falls.
//   SmoothCsgField: some child is a pair (Π, N) (a fuzzy part, a node with one below it). The
//     node combines the children's pairs; a membership child enters as its pair
//     (Π = min(1, 2μ), N = max(0, 2μ − 1)). Its blend is a blend of the possibilities and of the
//     necessities: the core (α = 1) blends only where the operator reaches 1 with both
//     arguments below 1 (lukasiewicz's min(1, x + y), for instance); for a strict conorm
//     (algebraic, einstein, bezier, ...) the core is the union of the children's cores and the
//     blend shows at α < 1 only.
// Both keep lower(α) ⊆ upper(α) and nesting in α (node_operator.h: the axiom N > 0 ⇒ Π = 1).
//
// Contract:
// - makeSmoothCsgNode builds the node of a document: it validates, replaces every crisp part
//   among the children, directly or below Zadeh nodes (CsgField), by its SmoothedPartField with
//   the node's LeafSmoothing (a nested smooth node keeps its own), and picks the world above.
//   Zadeh nodes in between keep their operation (min/max preserve each 0.5 level surface); one
//   whose children all become memberships becomes a MembershipCsgField with the zadeh operator,
//   with the same levels (min/max commute with the map of membership_field.h), so a smooth node
//   above it still combines memberships. Fuzzy parts keep their (Π, N): they are graded already.
// - union and intersection take two or more children (left fold, ((c0 ∘ c1) ∘ c2) ∘ …; smooth
//   operators are commutative but a blend is not associative, so the order of children matters
//   slightly); difference means ((c0 − c1) − c2) − …
// - boundsOver / membershipOver: NodeOperator's bounds of the children's bounds (sound when
//   theirs are).
// - boundingBox: csgBoundingBox of the (smoothed) children: the boundary values of
//   node_operator.h keep the support inside it.
// Errors (paths as in a node document): NodeOperator's under "operator" ("operator.name",
// "operator.n"), validateLeafSmoothing's ("range", "step.n"), and errc::kInvalidDocument
// "children" with fewer than two children or an empty one (the constructors check the children
// too).
#include <memory>
#include <mutex>
#include <vector>

#include "geometry/field/alpha_field.h"
#include "geometry/field/csg_field.h"
#include "geometry/field/membership_field.h"
#include "geometry/field/node_operator.h"
#include "geometry/field/smoothed_part_field.h"

namespace fsdb {

// The node `op` of `children` with `config` and `smoothing`, as the contract above says: a
// MembershipCsgField or a SmoothCsgField.
std::shared_ptr<const AlphaFieldSource> makeSmoothCsgNode(CsgOp op, const OperatorConfig& config,
                                                          const LeafSmoothing& smoothing,
                                                          std::vector<std::shared_ptr<const AlphaFieldSource>> children);

// The (Π, N) world. The children are taken as they are (makeSmoothCsgNode smooths crisp parts).
class SmoothCsgField : public AlphaFieldSource {
 public:
  SmoothCsgField(CsgOp op, NodeOperator nodeOperator, std::vector<std::shared_ptr<const AlphaFieldSource>> children);

  AlphaLevels levelsAt(const Vec3& p) const override;
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;
  std::uint64_t budgetExhaustions() const override { return sumBudgetExhaustions(children_); }

  const std::vector<std::shared_ptr<const AlphaFieldSource>>& children() const { return children_; }
  const NodeOperator& nodeOperator() const { return operator_; }

 private:
  CsgOp op_;
  NodeOperator operator_;
  std::vector<std::shared_ptr<const AlphaFieldSource>> children_;
};

// The membership world: μ' of the children's memberships.
class MembershipCsgField : public MembershipField {
 public:
  MembershipCsgField(CsgOp op, NodeOperator nodeOperator, std::vector<std::shared_ptr<const MembershipField>> children);

  double membership(const Vec3& p) const override;
  MembershipRange membershipOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;
  std::uint64_t budgetExhaustions() const override { return sumBudgetExhaustions(children_); }

  const std::vector<std::shared_ptr<const MembershipField>>& children() const { return children_; }
  const NodeOperator& nodeOperator() const { return operator_; }

 private:
  CsgOp op_;
  NodeOperator operator_;
  std::vector<std::shared_ptr<const MembershipField>> children_;
  // csgBoundingBox of the children, on the first boundingBox: a shape read only for its parts (the
  // linguistic search scores a stored shape's components) does not tighten its leaves' boxes.
  mutable std::once_flag boxOnce_;
  mutable Vec3 lo_, hi_;
};

// `field` with every crisp FuzzyPartField reached through CsgField nodes replaced by its
// SmoothedPartField, and every such CsgField whose children all become MembershipFields by a
// zadeh MembershipCsgField (other fields are returned as they are). A SharedField (a node several
// parents share) is smoothed once per call and stays shared while it is still an alpha source.
std::shared_ptr<const AlphaFieldSource> smoothCrispParts(const std::shared_ptr<const AlphaFieldSource>& field,
                                                         const LeafSmoothing& smoothing);

}  // namespace fsdb
