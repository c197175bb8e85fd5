#pragma once
// SmoothCsgField: a CSG node whose operator is a fuzzy set operator or a blend of the catalogue
// instead of Zadeh's min/max (SPEC §2 "operator"; seeds 000, 001). The combination of the
// children's (possibility, necessity) pairs, the blends on μ − 1/2 and the bounds are those of
// geometry/node_operator.h; crisp parts become graded solids μ(F(P)) (seed 000 §2.1,
// geometry/smoothed_part_field.h).
//
// Contract:
// - union and intersection take two or more children (left fold, ((c0 ∘ c1) ∘ c2) ∘ …; smooth
//   operators are commutative but a blend is not associative, so the order of children matters
//   slightly); difference means ((c0 − c1) − c2) − …
// - Every crisp part among the children, directly or below Zadeh nodes (CsgField), is replaced
//   by its SmoothedPartField with the node's LeafSmoothing (a nested smooth node keeps its own).
//   Zadeh nodes in between keep their operation, on the smoothed memberships (min/max preserve
//   each 0.5 level surface). Fuzzy parts keep their (Π, N): they are graded already.
// - boundsOver: NodeOperator's bounds of the children's bounds (sound when theirs are).
// - boundingBox: csgBoundingBox of the (smoothed) children: the boundary values of
//   node_operator.h keep the support inside it.
// Errors (paths as in a node document): NodeOperator's under "operator" ("operator.name",
// "operator.n"), validateLeafSmoothing's ("range", "step.n"), and errc::kInvalidDocument
// "children" with fewer than two children.
#include <memory>
#include <vector>

#include "geometry/alpha_field.h"
#include "geometry/csg_field.h"
#include "geometry/node_operator.h"
#include "geometry/smoothed_part_field.h"

namespace fsdb {

class SmoothCsgField : public AlphaFieldSource {
 public:
  SmoothCsgField(CsgOp op, const OperatorConfig& config, const LeafSmoothing& smoothing,
                 std::vector<std::shared_ptr<const AlphaFieldSource>> children);

  AlphaLevels levelsAt(const Vec3& p) const override;
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;

  // The children after crisp parts were smoothed.
  const std::vector<std::shared_ptr<const AlphaFieldSource>>& children() const { return children_; }
  const NodeOperator& nodeOperator() const { return operator_; }

 private:
  CsgOp op_;
  NodeOperator operator_;
  std::vector<std::shared_ptr<const AlphaFieldSource>> children_;
};

// `field` with every crisp FuzzyPartField reached through CsgField nodes replaced by its
// SmoothedPartField (other fields are returned as they are).
std::shared_ptr<const AlphaFieldSource> smoothCrispParts(const std::shared_ptr<const AlphaFieldSource>& field,
                                                         const LeafSmoothing& smoothing);

}  // namespace fsdb
