#pragma once
// SmoothedPartField: a crisp part as a graded solid under a CSG node with a smooth operator
// (geometry/field/smooth_csg_field.h). A crisp part's indicator (0/1) does not blend at all
// (T(1, 0) = 0), so Li & Tian, §2.1 applies: its membership becomes
//   μ(p) = step(−d(p) / R)
// with d the part's pseudo signed distance (placed_superquadric.h: negative inside, in world
// units), `step` a smooth unit step of the catalogue rising from 0 at −1 to 1 at +1 with
// step(0) = 1/2 (so the part's own surface is exactly the 0.5 level), and R > 0 the node's
// rising range. Memberships below 2^-24 are flushed to 0: a step with unbounded tails (sigmoid)
// would leave the whole grown box slightly positive, where node operators get no boundary values
// (Ext_max adds delta/4 where both memberships are positive; node_operator.h).
// It is a MembershipField (membership_field.h): smooth nodes combine μ itself, and its levels are
// Π = min(1, 2μ), N = max(0, 2μ − 1), so its core is the part itself ({μ ≥ 1/2}), upper(α) =
// {μ ≥ α/2} and lower(α) = {μ ≥ 1 − α/2} (the band of width R around the surface at α = 0).
//
// Support: μ = 0 outside the part's bounding box grown by R on every side. For an undeformed part
// step(−d/R) is 0 there anyway (the radial pseudo distance is at least the Euclidean distance to
// the solid, hence >= R); for a tapered, twisted or bent part the pseudo distance is not a
// distance bound, and this cut keeps boundingBox and boundsOver sound by construction.
// membershipOver (and so boundsOver): 0 on boxes outside the grown box, else the trivial [0, 1]
// (there is no interval evaluation of d yet, so blocks inside the part are never proven uniform).
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/membership_field.h"
#include "geometry/operators/operator_catalog.h"
#include "geometry/superquadric/placed_superquadric.h"

namespace fsdb {

// The default rising range: 10% of the part's smallest canonical half-length min(A, B, C)
// (docs/api.md §2), times its scale (world units).
double defaultSmoothingRange(const PlacedSuperquadric& part);

// A node's "range" and "step" (docs/api.md §2): range in world units, nullopt for
// defaultSmoothingRange of each part; step default polynomial{n = 3} (Li, eq. 6, C^2).
struct LeafSmoothing {
  std::optional<double> range;
  OperatorConfig step{"polynomial", {{"n", 3.0}}, {}};
};

// Validates: range > 0 and finite (errc::kInvalidParameter, path "range"); step of kind "step"
// with unit range (validateNestedStep; paths "step...") and step(0) = 1/2 (path "step.name").
// Returns the step function.
std::shared_ptr<const UnaryFunction> validateLeafSmoothing(const LeafSmoothing& smoothing);

class SmoothedPartField : public MembershipField {
 public:
  // `leaf` must be crisp (FuzzyPartField::isCrisp, else errc::kInvalidDocument, path "part");
  // validateLeafSmoothing's errors. The leaf is kept: its bounding box (a tightening that costs
  // about 2 ms) is computed on the first membership or box asked for, not here, so a shape read
  // only for its components (the linguistic search scores a stored shape's parts) pays nothing.
  SmoothedPartField(std::shared_ptr<const FuzzyPartField> leaf, const LeafSmoothing& smoothing);

  double membership(const Vec3& p) const override;  // μ(p) above
  MembershipRange membershipOver(const Vec3& lo, const Vec3& hi) const override;
  void boundingBox(Vec3* lo, Vec3* hi) const override;

  double range() const { return range_; }

 private:
  void growBox() const;  // lo_, hi_ on first use
  std::shared_ptr<const FuzzyPartField> leaf_;
  PreparedSuperquadric part_;
  double range_;
  std::shared_ptr<const UnaryFunction> step_;
  mutable std::once_flag boxOnce_;
  mutable std::atomic<bool> boxReady_{false};  // set after boxOnce_ ran: membership's fast path
  mutable Vec3 lo_, hi_;  // the part's bounding box grown by range_
};

}  // namespace fsdb
