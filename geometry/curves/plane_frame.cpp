#include "geometry/curves/plane_frame.h"

#include <algorithm>
#include <cmath>

namespace fsdb {
namespace {

Vec2 scaled(const Vec2& v, int e) { return {std::ldexp(v.x, e), std::ldexp(v.y, e)}; }

// Coordinates of at most 2^500 and at least 2^-500 in magnitude are used as they are: their
// differences and products of two of them stay in the normal range.
constexpr int kComfortExponent = 500;

}  // namespace

PlaneFrame PlaneFrame::normalizing(const std::vector<Vec2>& points) {
  PlaneFrame f;
  double largest = 0;
  for (const Vec2& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  if (largest > 0 && (std::ilogb(largest) > kComfortExponent || std::ilogb(largest) < -kComfortExponent))
    f.outer = std::ilogb(largest) + 1;  // the scaled points lie in (-1, 1)
  if (points.empty()) return f;
  Vec2 lo = scaled(points.front(), -f.outer), hi = lo;
  for (const Vec2& p : points) {
    const Vec2 q = scaled(p, -f.outer);
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  f.centre = {0.5 * lo.x + 0.5 * hi.x, 0.5 * lo.y + 0.5 * hi.y};  // halves first: no overflow
  double spread = 0;
  for (const Vec2& p : points) {
    const Vec2 d = scaled(p, -f.outer) - f.centre;
    spread = std::max({spread, std::abs(d.x), std::abs(d.y)});
  }
  if (spread > 0) f.inner = -(std::ilogb(spread) + 1);
  return f;
}

Vec2 PlaneFrame::toLocal(const Vec2& world) const { return scaled(scaled(world, -outer) - centre, inner); }

Vec2 PlaneFrame::toWorld(const Vec2& local) const { return scaled(scaled(local, -inner) + centre, outer); }

double PlaneFrame::toLocalLength(double world) const { return std::ldexp(world, inner - outer); }

double PlaneFrame::toWorldLength(double local) const { return std::ldexp(local, outer - inner); }

Vec2 PlaneFrame::toWorldVector(const Vec2& local) const { return scaled(local, outer - inner); }

}  // namespace fsdb
