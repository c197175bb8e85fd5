#pragma once
// MembershipField: a graded solid given by one membership μ(p) in [0, 1] whose 0.5 level is its
// shape (Li & Tian, §2.1: the solid F ≥ 0 is the level set μ(F) ≥ 0.5), seen as an alpha field
// (geometry/field/alpha_field.h). Crisp parts under smooth CSG nodes become such fields
// (geometry/field/smoothed_part_field.h), and so do the nodes that combine only them
// (geometry/field/smooth_csg_field.h: MembershipCsgField).
//
// Levels of a membership. A membership is neither a possibility nor a necessity: its shape is
// the 0.5 level, and reading μ as both (Π = N = μ) gives lower(α) = {μ ≥ 1 − α} and upper(α) =
// {μ ≥ α}, which swap above α = 1/2 (lower ⊄ upper: docs/api.md §3 broken). fsdb reads it as
//   Π = min(1, 2μ),  N = max(0, 2μ − 1)        (so μ = (Π + N)/2)
// i.e. u = min(1, 2μ) and l = 2 − 2μ where μ > 1/2, else kNeverInside:
//   upper(α) = {μ ≥ α/2},  lower(α) = {μ ≥ 1 − α/2} (at α = 1: μ > 1/2, the measure-zero
//   caveat of node_operator.h),  the core upper(1) = {μ ≥ 1/2} = the (blended) shape;
// as α falls from 1 upper(α) grows and lower(α) shrinks, both from the shape: nested in α, and
// lower(α) ⊆ lower(1) ⊆ core ⊆ upper(α). N > 0 ⇒ Π = 1 holds (node_operator.h's axiom), with N
// and Π exact in double (2μ and, for μ >= 1/2, 2μ − 1 are exact), then rounded as
// levelsFromPossibility rounds: u = 1 exactly where μ >= 1/2. The map is the linear one whose
// core is the 0.5 level and whose α = 0 cuts are the whole support and nothing (upper(0) =
// {μ > 0}, lower(0) = {μ = 1}): the step's band [−R, R] around the surface is the uncertainty.
//
// Where memberships meet: two memberships combine as memberships (the node operator on μ,
// Li & Tian's blend, whose 0.5 level is the blended surface), and the result is again a membership;
// only where a membership meets a pair (a fuzzy part's (Π, N) at a node, or the voxel grid at
// the root through levelsAt) does it become the pair above. Zadeh's min/max commute with the map
// (it is non-decreasing, and 1 − μ maps to (1 − N, 1 − Π)), so a zadeh node gives the same levels
// either way; applying a smooth operator to the pairs instead would not blend at α = 1 (most
// conorms reach 1 only where one argument does).
//
// boundsOver: the map of membershipOver's range (the map is monotone: u rises and l falls with
// μ), so it is sound when membershipOver is.
#include "geometry/field/alpha_field.h"
#include "geometry/field/node_operator.h"

namespace fsdb {

// The pair of a membership (above), as float levels.
AlphaLevels levelsFromMembership(double membership);
// Bounds of the levels of memberships in [range.lo, range.hi].
AlphaLevelBounds boundsFromMembership(MembershipRange range);

class MembershipField : public AlphaFieldSource {
 public:
  // μ(p) in [0, 1]; 0 outside boundingBox().
  virtual double membership(const Vec3& p) const = 0;
  // Guaranteed bounds of μ over the axis-aligned box [lo, hi].
  virtual MembershipRange membershipOver(const Vec3& lo, const Vec3& hi) const = 0;

  AlphaLevels levelsAt(const Vec3& p) const final { return levelsFromMembership(membership(p)); }
  AlphaLevelBounds boundsOver(const Vec3& lo, const Vec3& hi) const final {
    return boundsFromMembership(membershipOver(lo, hi));
  }
};

}  // namespace fsdb
