#pragma once
// Vec3: a point or direction in 3-space, in double precision. Deliberately minimal: the
// geometry layer needs addition, scaling, dot and cross products and a length that neither
// overflows nor underflows; anything more belongs to a real linear-algebra library.
#include <algorithm>
#include <cmath>
#include <limits>

namespace fsdb {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(const Vec3& a, double s) { return s * a; }
inline Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
inline bool operator==(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
inline bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }

inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Euclidean length. std::hypot scales internally, so |(1e200, 1e200, 0)| and
// |(1e-200, 0, 0)| come out right where sqrt(dot(a, a)) would give inf or 0. Infinite
// components are answered first: libstdc++'s three-argument hypot divides by the largest
// component and returns NaN for them.
inline double norm(const Vec3& a) {
  if (std::isinf(a.x) || std::isinf(a.y) || std::isinf(a.z))
    return std::numeric_limits<double>::infinity();
  return std::hypot(a.x, a.y, a.z);
}

// Per coordinate: the corners of the hull (min) and of the overlap (max) of boxes.
inline Vec3 componentMin(const Vec3& a, const Vec3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 componentMax(const Vec3& a, const Vec3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

inline bool isFinite(const Vec3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// Whether the closed axis-aligned boxes [alo, ahi] and [blo, bhi] share a point.
inline bool boxesMeet(const Vec3& alo, const Vec3& ahi, const Vec3& blo, const Vec3& bhi) {
  return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y && alo.z <= bhi.z &&
         blo.z <= ahi.z;
}

}  // namespace fsdb
