#include "geometry/field/membership_field.h"

#include <algorithm>

namespace fsdb {

AlphaLevels levelsFromMembership(double membership) {
  const double twice = 2.0 * std::clamp(membership, 0.0, 1.0);  // exact
  // Π = min(1, 2μ), N = max(0, 2μ − 1) (membership_field.h); 2μ − 1 is exact for 2μ in [1, 2].
  return levelsFromPossibility(std::min(1.0, twice), std::max(0.0, twice - 1.0));
}

AlphaLevelBounds boundsFromMembership(MembershipRange range) {
  // u is non-decreasing and l non-increasing in μ (levelsFromPossibility keeps both directions).
  const AlphaLevels lo = levelsFromMembership(range.lo), hi = levelsFromMembership(range.hi);
  return {lo.upper, hi.upper, hi.lower, lo.lower};
}

}  // namespace fsdb
