#include "geometry/superquadric/placed_superquadric.h"

#include <algorithm>
#include <limits>

#include "geometry/superquadric/deformation.h"
#include "geometry/core/error.h"

namespace fsdb {

void PlacedSuperquadric::validate() const {
  try {
    params.validate();
  } catch (const Error& e) {
    throw e.withPathPrefix("params");
  }
  try {
    placement.validate();
  } catch (const Error& e) {
    throw e.withPathPrefix("transform");
  }
}

namespace {

// The evaluation shared by PlacedSuperquadric (frame built per call) and
// PreparedSuperquadric (frame built once).
Vec3 toCanonicalIn(const SuperquadricParams& params, const PlacementFrame& frame,
                   const Vec3& world) {
  return undeformPoint(params, frame.toLocal(world));
}

double insideOutsideIn(const SuperquadricParams& params, const PlacementFrame& frame,
                       const Vec3& world) {
  return insideOutside(params, toCanonicalIn(params, frame, world));
}

double pseudoDistanceIn(const SuperquadricParams& params, const PlacementFrame& frame,
                        const Vec3& world) {
  // Scaling is the only part of the placement that changes lengths; rotation and
  // translation are isometries. The canonical value may be saturated already; keep the
  // product finite too.
  const double d = frame.scale() * pseudoDistance(params, toCanonicalIn(params, frame, world));
  return std::min(d, std::numeric_limits<double>::max());
}

}  // namespace

Vec3 PlacedSuperquadric::toCanonical(const Vec3& world) const {
  return toCanonicalIn(params, PlacementFrame(placement), world);
}

Vec3 PlacedSuperquadric::toWorld(const Vec3& canonical) const {
  return placeToWorld(placement, deformPoint(params, canonical));
}

double PlacedSuperquadric::insideOutside(const Vec3& world) const {
  return insideOutsideIn(params, PlacementFrame(placement), world);
}

double PlacedSuperquadric::pseudoDistance(const Vec3& world) const {
  return pseudoDistanceIn(params, PlacementFrame(placement), world);
}

namespace {
const PlacedSuperquadric& validated(const PlacedSuperquadric& part) {
  part.validate();
  return part;
}
}  // namespace

PreparedSuperquadric::PreparedSuperquadric(const PlacedSuperquadric& part)
    : params_(validated(part).params), frame_(part.placement) {}

Vec3 PreparedSuperquadric::toCanonical(const Vec3& world) const {
  return toCanonicalIn(params_, frame_, world);
}

double PreparedSuperquadric::insideOutside(const Vec3& world) const {
  return insideOutsideIn(params_, frame_, world);
}

double PreparedSuperquadric::pseudoDistance(const Vec3& world) const {
  return pseudoDistanceIn(params_, frame_, world);
}

}  // namespace fsdb
