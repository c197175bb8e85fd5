#pragma once
// Vec2: a point or direction in the plane (Bernardes, Wu & D'Ottaviano's fair curves live in the
// plane). Minimal on purpose, like vec3.h: sums, scaling, dot, the scalar cross product and the
// length.
#include <cmath>

namespace fsdb {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator-(const Vec2& a) { return {-a.x, -a.y}; }
inline Vec2 operator*(double s, const Vec2& a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(const Vec2& a, double s) { return s * a; }
inline double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
// The z component of the 3-d cross product: > 0 when b is counter-clockwise from a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline double length(const Vec2& a) { return std::hypot(a.x, a.y); }

// The unit vector at `deg` degrees from the x axis (Bernardes, Wu & D'Ottaviano, §4: the reference
// line).
inline Vec2 unitAtDegrees(double deg) {
  const double r = deg * (M_PI / 180.0);
  return {std::cos(r), std::sin(r)};
}
// The direction of v in degrees from the x axis, in (-180, 180] (atan2's range).
inline double degreesOf(const Vec2& v) { return std::atan2(v.y, v.x) * (180.0 / M_PI); }

}  // namespace fsdb
