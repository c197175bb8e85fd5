#pragma once
// CsgField: the alpha field of a CSG tree of fuzzy solids (Zhang, Pham & Chen, §2.3, §3.2;
// docs/api.md §3).
//
// A node is a leaf (any AlphaFieldSource, e.g. a fuzzy superquadric part) or a Boolean of
// child nodes. Children are shared pointers, so a subtree referenced by several trees (or twice
// in one, a DAG) is built once. With the default (Zadeh) semantics the Booleans of alpha_field.h
// are exact for every α at once, so the whole tree is one AlphaFieldSource: the voxel layer
// evaluates and prunes it in a single pass, never materialising a grid per node.
//
// Contract:
// - union and intersection take two or more children (n-ary, order irrelevant); difference
//   takes two or more and means ((c0 − c1) − c2) − …
// - boundsOver combines the children's bounds with the same monotone formulas, so it stays
//   sound when theirs are.
// - boundingBox: union → hull of the children's; intersection → their overlap (an empty
//   overlap collapses to a point: nothing is inside); difference → the first child's.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "geometry/field/alpha_field.h"

namespace fsdb {

enum class CsgOp { kUnion, kIntersection, kDifference };

// The operation's name in shape documents ("union", "intersection", "difference"), and the
// operation of a name (false for any other word).
const char* csgOpName(CsgOp op);
bool csgOpFromName(const std::string& name, CsgOp* op);

class CsgField : public AlphaFieldSource {
 public:
  // Throws fsdb::Error(errc::kInvalidDocument, ..., "children") with fewer than two children.
  CsgField(CsgOp op, std::vector<std::shared_ptr<const AlphaFieldSource>> children);

  AlphaLevels levelsAt(const Vec3& p) const override;
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;
  // Per block, each child is bounded over the block first: a child whose bounding box misses the
  // block is background there without any bound, a child whose bounds are uniform over the block
  // enters as that one value, and only the rest are sampled (their own sampleBlock). Children
  // that cannot change the result (background in a union or as a subtrahend, anything once an
  // intersection or difference is empty, anything once a union is (1, 0)) are never sampled.
  void sampleBlock(const BlockLattice& b, AlphaLevels* out) const override;
  std::uint64_t budgetExhaustions() const override { return sumBudgetExhaustions(children_); }

  CsgOp op() const { return op_; }
  const std::vector<std::shared_ptr<const AlphaFieldSource>>& children() const { return children_; }

 private:
  CsgOp op_;
  std::vector<std::shared_ptr<const AlphaFieldSource>> children_;
  void ensureChildBoxes() const;  // fills childLo_, childHi_ once
  mutable std::once_flag boxesOnce_;
  mutable std::vector<Vec3> childLo_, childHi_;  // the children's bounding boxes
};

// Exact combination of bounds for each operation (interval extension of alpha_field.h's
// formulas, which are monotone in every argument).
AlphaLevelBounds boundsUnion(const AlphaLevelBounds& a, const AlphaLevelBounds& b);
AlphaLevelBounds boundsIntersection(const AlphaLevelBounds& a, const AlphaLevelBounds& b);
AlphaLevelBounds boundsDifference(const AlphaLevelBounds& a, const AlphaLevelBounds& b);

// alpha_field.h's combination for `op`, and its bounds counterpart.
AlphaLevels alphaCombine(CsgOp op, AlphaLevels a, AlphaLevels b);
AlphaLevelBounds boundsCombine(CsgOp op, const AlphaLevelBounds& a, const AlphaLevelBounds& b);

// The bounding box rule of the contract above, for any node whose support stays inside it.
void csgBoundingBox(CsgOp op, const std::vector<std::shared_ptr<const AlphaFieldSource>>& children, Vec3* lo,
                    Vec3* hi);

}  // namespace fsdb
