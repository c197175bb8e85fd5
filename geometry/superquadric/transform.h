#pragma once
// Placement of a part in the world: uniform scale, then rotation by `deg` degrees about
// `axis` (right-handed, Rodrigues' formula), then translation (docs/api.md §2, "transform":
// {"translate":[x,y,z], "rotate":{"axis":[...],"deg":d}, "scale":s}). Every placement is
// invertible; placeToWorld and placeToLocal are exact inverses up to rounding.
//
// Validity: translate finite, axis finite and non-zero (any length; it is normalised),
// deg finite, scale finite and > 0. validate() throws fsdb::Error(kInvalidParameter) with
// the path of the bad value as it appears in the document ("scale", "rotate.axis",
// "rotate.deg", "translate").
#include "geometry/core/vec3.h"

namespace fsdb {

// A rotation as a 3x3 orthonormal matrix, built once and applied many times.
class Rotation {
 public:
  Rotation();  // identity
  // Rodrigues: R = cos θ·I + sin θ·[k]x + (1 − cos θ)·k kᵀ, k = axis/|axis|, θ = deg in degrees.
  // Multiples of 90° are exact (cos 90° is 0, not 6e-17). Precondition: axis finite, non-zero.
  static Rotation fromAxisAngle(const Vec3& axis, double deg);

  Vec3 apply(const Vec3& v) const;         // R·v
  Vec3 applyInverse(const Vec3& v) const;  // Rᵀ·v = R⁻¹·v

 private:
  double m_[3][3];
};

struct Placement {
  Vec3 translate{0.0, 0.0, 0.0};
  Vec3 axis{0.0, 0.0, 1.0};
  double deg = 0.0;
  double scale = 1.0;

  void validate() const;
};

// A placement prepared for repeated use: the rotation matrix is computed once.
class PlacementFrame {
 public:
  explicit PlacementFrame(const Placement& placement);  // precondition: placement validated

  Vec3 toWorld(const Vec3& local) const;  // translate + R·(scale·local)
  Vec3 toLocal(const Vec3& world) const;  // Rᵀ·(world − translate) / scale
  double scale() const { return scale_; }

 private:
  Rotation rotation_;
  Vec3 translate_;
  double scale_;
};

// One-off conveniences over PlacementFrame.
Vec3 placeToWorld(const Placement& placement, const Vec3& local);
Vec3 placeToLocal(const Placement& placement, const Vec3& world);

}  // namespace fsdb
