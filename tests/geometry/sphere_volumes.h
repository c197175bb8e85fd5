#pragma once
// Closed-form volumes of balls and of the intersection of two balls, for the voxel tests.
#include <algorithm>
#include <cmath>

namespace fsdb {
namespace testing {

inline double ballVolume(double r) { return r > 0.0 ? 4.0 / 3.0 * M_PI * r * r * r : 0.0; }

// Volume of the intersection of balls of radii R and r whose centres are d apart.
inline double lensVolume(double R, double r, double d) {
  if (R <= 0.0 || r <= 0.0 || d >= R + r) return 0.0;
  if (d <= std::fabs(R - r)) return ballVolume(std::min(R, r));
  return M_PI * (R + r - d) * (R + r - d) * (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) /
         (12 * d);
}

}  // namespace testing
}  // namespace fsdb
