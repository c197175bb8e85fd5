#include "geometry/superquadric/transform.h"

#include <charconv>
#include <cmath>
#include <string>

#include "geometry/core/error.h"
#include "geometry/core/number_format.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;

// sin and cos of an angle in degrees, exact at multiples of 90°. The angle is reduced
// exactly (std::remainder) to r in [−180, 180], split into q quarter turns plus a rest in
// [−45, 45] (exact by Sterbenz' lemma), and the quarter turns are applied by swapping signs.
void sinCosDegrees(double deg, double* s, double* c) {
  const double r = std::remainder(deg, 360.0);
  const int q = static_cast<int>(std::lround(r / 90.0));
  const double rest = (r - 90.0 * q) * (kPi / 180.0);
  const double sr = std::sin(rest), cr = std::cos(rest);
  switch (q) {
    case 0:
      *s = sr;
      *c = cr;
      break;
    case 1:
      *s = cr;
      *c = -sr;
      break;
    case -1:
      *s = -cr;
      *c = sr;
      break;
    default:  // ±2: half a turn
      *s = -sr;
      *c = -cr;
      break;
  }
}

}  // namespace

Rotation::Rotation() : m_{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}} {}

Rotation Rotation::fromAxisAngle(const Vec3& axis, double deg) {
  const Vec3 k = axis / norm(axis);
  double s, c;
  sinCosDegrees(deg, &s, &c);
  const double t = 1.0 - c;
  Rotation r;
  // Rodrigues' rotation formula in matrix form: R = c·I + s·[k]x + t·k kᵀ.
  r.m_[0][0] = c + t * k.x * k.x;
  r.m_[0][1] = t * k.x * k.y - s * k.z;
  r.m_[0][2] = t * k.x * k.z + s * k.y;
  r.m_[1][0] = t * k.y * k.x + s * k.z;
  r.m_[1][1] = c + t * k.y * k.y;
  r.m_[1][2] = t * k.y * k.z - s * k.x;
  r.m_[2][0] = t * k.z * k.x - s * k.y;
  r.m_[2][1] = t * k.z * k.y + s * k.x;
  r.m_[2][2] = c + t * k.z * k.z;
  return r;
}

Vec3 Rotation::apply(const Vec3& v) const {
  return {m_[0][0] * v.x + m_[0][1] * v.y + m_[0][2] * v.z,
          m_[1][0] * v.x + m_[1][1] * v.y + m_[1][2] * v.z,
          m_[2][0] * v.x + m_[2][1] * v.y + m_[2][2] * v.z};
}

Vec3 Rotation::applyInverse(const Vec3& v) const {
  // A rotation matrix is orthogonal: its inverse is its transpose.
  return {m_[0][0] * v.x + m_[1][0] * v.y + m_[2][0] * v.z,
          m_[0][1] * v.x + m_[1][1] * v.y + m_[2][1] * v.z,
          m_[0][2] * v.x + m_[1][2] * v.y + m_[2][2] * v.z};
}

void Placement::validate() const {
  if (!isFinite(translate))
    throw Error(errc::kInvalidParameter, "translate must have finite coordinates", "translate");
  if (!isFinite(axis) || !(norm(axis) > 0.0))
    throw Error(errc::kInvalidParameter, "rotate.axis must be a finite, non-zero vector",
                "rotate.axis");
  if (!std::isfinite(deg))
    throw Error(errc::kInvalidParameter,
                "rotate.deg must be a finite number of degrees; got " + formatNumber(deg),
                "rotate.deg");
  if (!(scale > 0.0 && std::isfinite(scale)))
    throw Error(errc::kInvalidParameter,
                "scale must be a finite number > 0; got " + formatNumber(scale), "scale");
}

PlacementFrame::PlacementFrame(const Placement& placement)
    : rotation_(Rotation::fromAxisAngle(placement.axis, placement.deg)),
      translate_(placement.translate),
      scale_(placement.scale) {}

Vec3 PlacementFrame::toWorld(const Vec3& local) const {
  return rotation_.apply(scale_ * local) + translate_;
}

Vec3 PlacementFrame::toLocal(const Vec3& world) const {
  return rotation_.applyInverse(world - translate_) / scale_;
}

Vec3 placeToWorld(const Placement& placement, const Vec3& local) {
  return PlacementFrame(placement).toWorld(local);
}

Vec3 placeToLocal(const Placement& placement, const Vec3& world) {
  return PlacementFrame(placement).toLocal(world);
}

}  // namespace fsdb
