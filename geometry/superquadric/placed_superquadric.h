#pragma once
// A superquadric part placed in the world: canonical solid (superquadric.h), deformed by
// taper -> twist -> bend (deformation.h), then placed by scale -> rotate -> translate
// (transform.h). A world point is evaluated by undoing these in reverse order (docs/api.md §2):
// unplace, unbend, untwist, untaper, then the canonical inside-outside function.
//
// Contract: call validate() once; the evaluation functions assume valid parameters.
// PlacedSuperquadric is the value (what a part document holds); PreparedSuperquadric
// evaluates the same functions for many points without rebuilding the rotation per call.
//  * insideOutside(w) = F(canonical point of w): inside iff <= 1; saturates like F.
//  * pseudoDistance(w) = scale · pseudoDistance(canonical point of w): the canonical radial
//    pseudo distance in world units. Its sign and zero set are exact (those of F − 1); its
//    magnitude is the Euclidean distance only for undeformed spheres (and is a length-like
//    estimate otherwise: deformations are not isometries).
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"
#include "geometry/core/vec3.h"

namespace fsdb {

struct PlacedSuperquadric {
  SuperquadricParams params;
  Placement placement;

  // Validates params then placement; the error path is prefixed as in a part document
  // ("params.kv", "transform.scale", "transform.rotate.axis").
  void validate() const;

  Vec3 toCanonical(const Vec3& world) const;  // undeformPoint(placeToLocal(world))
  Vec3 toWorld(const Vec3& canonical) const;  // placeToWorld(deformPoint(canonical))

  double insideOutside(const Vec3& world) const;
  double pseudoDistance(const Vec3& world) const;
};

// A placed part checked once and prepared for evaluating many points (voxel grids): the
// placement's rotation matrix is built in the constructor instead of on every call. Same
// results as the PlacedSuperquadric functions, bit for bit.
class PreparedSuperquadric {
 public:
  // Validates (PlacedSuperquadric::validate) and throws its fsdb::Error.
  explicit PreparedSuperquadric(const PlacedSuperquadric& part);

  const SuperquadricParams& params() const { return params_; }

  Vec3 toCanonical(const Vec3& world) const;
  double insideOutside(const Vec3& world) const;
  double pseudoDistance(const Vec3& world) const;

 private:
  SuperquadricParams params_;
  PlacementFrame frame_;
};

}  // namespace fsdb
