#include "geometry/placed_superquadric.h"

#include <algorithm>
#include <limits>

#include "geometry/deformation.h"
#include "geometry/error.h"

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

Vec3 PlacedSuperquadric::toCanonical(const Vec3& world) const {
  return undeformPoint(params, placeToLocal(placement, world));
}

Vec3 PlacedSuperquadric::toWorld(const Vec3& canonical) const {
  return placeToWorld(placement, deformPoint(params, canonical));
}

double PlacedSuperquadric::insideOutside(const Vec3& world) const {
  return fsdb::insideOutside(params, toCanonical(world));
}

double PlacedSuperquadric::pseudoDistance(const Vec3& world) const {
  // Scaling is the only part of the placement that changes lengths; rotation and
  // translation are isometries. The canonical value may be saturated already; keep the
  // product finite too.
  const double d = placement.scale * fsdb::pseudoDistance(params, toCanonical(world));
  return std::min(d, std::numeric_limits<double>::max());
}

}  // namespace fsdb
