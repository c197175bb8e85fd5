#pragma once
// PlaneFrame: a similarity of the plane, world = 2^outer (2^-inner local + centre), that maps a
// point set to local coordinates of spread about 1 centred on 0. A fair curve depends only on
// angles and relative lengths (Bernardes, Wu & D'Ottaviano, §4: "only the relative magnitude
// matters"), so it is built in local coordinates: points a subnormal distance apart or near the
// largest double then neither underflow nor overflow in differences, dot products and lengths.
// Both scalings are powers of two (exact unless a result leaves the normal range); the only
// rounding is the translation by the centre, no worse than a difference of world coordinates.
#include <vector>

#include "geometry/core/vec2.h"

namespace fsdb {

struct PlaneFrame {
  int outer = 0;  // world = 2^outer * scaled
  Vec2 centre;    // the bounding box centre of the scaled points
  int inner = 0;  // local = 2^inner * (scaled - centre)

  // brief: the frame of a set of finite points: local coordinates lie in (-1, 1), the largest
  //        |coordinate| in [0.5, 1) (points all equal: local 0).
  // note: points near 0 or near the double range are first scaled by a power of two to about 1.
  static PlaneFrame normalizing(const std::vector<Vec2>& points);

  Vec2 toLocal(const Vec2& world) const;
  // note: may be infinite where the local point lies beyond the double range in world units.
  Vec2 toWorld(const Vec2& local) const;
  // Lengths and derivatives (vectors) scale by 2^(inner - outer) into local units.
  double toLocalLength(double world) const;
  double toWorldLength(double local) const;
  Vec2 toWorldVector(const Vec2& local) const;
};

}  // namespace fsdb
