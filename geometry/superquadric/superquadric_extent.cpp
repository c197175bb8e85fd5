#include "geometry/superquadric/superquadric_extent.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/deformation.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Box3 {
  Interval x, y, z;
};

// sin γ / γ (= 1 at 0): even, falling in |γ| on [0, π]; beyond π it lies in
// [−0.21723362821122166, 1/π] (its least value, at γ = 4.4934).
double sincAt(double g) {
  if (std::fabs(g) < 1e-4) return 1.0 - g * g / 6.0;
  return std::sin(g) / g;
}
Interval sincRange(const Interval& g) {
  if (g.lo >= -kPi && g.hi <= kPi) return {sincAt(magnitude(g)), sincAt(mignitude(g))};
  return {-0.21723362821122166, 1.0};
}

// (1 − cos γ) / γ (= 0 at 0): odd, rising on [−γ*, γ*] and falling from γ* to π, with
// γ* = 2.3311223704144224 (γ sin γ = 1 − cos γ) and peak 0.7246113537767085; beyond π its
// magnitude is below 2/π, so the peak bounds it everywhere.
double versineAt(double g) {
  if (std::fabs(g) < 1e-4) return 0.5 * g - g * g * g / 24.0;
  return (1.0 - std::cos(g)) / g;
}
Interval versineRange(const Interval& g) {
  constexpr double kPeakAt = 2.3311223704144224, kPeak = 0.7246113537767085;
  if (!(g.lo >= -kPi && g.hi <= kPi)) return {-kPeak, kPeak};
  const double a = versineAt(g.lo), b = versineAt(g.hi);
  Interval r{std::min(a, b), std::max(a, b)};
  if (contains(g, kPeakAt)) r.hi = kPeak;
  if (contains(g, -kPeakAt)) r.lo = -kPeak;
  return r;
}

// The forward maps of deformation.h and transform.h over a cell of canonical points and the
// parameter box, in interval arithmetic.
class ForwardMap {
 public:
  explicit ForwardMap(const PartBox& part) : q_(part.params), pl_(part.placement) {
    c_ = mul(q_.a1, q_.a3);
    const Rotation r = Rotation::fromAxisAngle(pl_.axis, mid(pl_.deg));
    const Vec3 ex = r.apply({1, 0, 0}), ey = r.apply({0, 1, 0}), ez = r.apply({0, 0, 1});
    rot_[0][0] = ex.x, rot_[1][0] = ex.y, rot_[2][0] = ex.z;
    rot_[0][1] = ey.x, rot_[1][1] = ey.y, rot_[2][1] = ey.z;
    rot_[0][2] = ez.x, rot_[1][2] = ez.y, rot_[2][2] = ez.z;
    // Angles within δ of the mid angle move a point v by at most the chord 2·sin(δ/2)·|v|.
    const double delta = std::min(0.5 * width(pl_.deg) * kPi / 180.0, kPi);
    chord_ = 2.0 * std::sin(0.5 * delta);
  }

  Box3 operator()(const Box3& cell) const {
    const Interval zc = div(cell.z, c_);
    // Taper: X = x(kx·z/C + 1), Y = y(ky·z/C + 1).
    Interval x = mul(cell.x, add(mul(q_.kx, zc), Interval{1.0, 1.0}));
    Interval y = mul(cell.y, add(mul(q_.ky, zc), Interval{1.0, 1.0}));
    const Interval z = cell.z;
    if (!isPoint(q_.t, 0.0)) turnEnclosure(mul(q_.t, zc), &x, &y);  // twist by θ = t·z/C
    Interval bx = x, bz = z;
    if (!isPoint(q_.kv, 0.0)) {
      // Bend (γ = k·z): X = x·cos γ + z·(1 − cos γ)/γ, Z = z·sin γ/γ − x·sin γ, the forms of
      // deformation.h rewritten so that k = 0 needs no division.
      const Interval g = mul(q_.kv, z);
      const Interval cg = cos(g), sg = sin(g);
      bx = add(mul(x, cg), mul(z, versineRange(g)));
      bz = sub(mul(z, sincRange(g)), mul(x, sg));
    }
    // Placement: translate + R·(scale·v), R within the chord of the mid angle's turn.
    const Interval v[3] = {mul(pl_.scale, bx), mul(pl_.scale, y), mul(pl_.scale, bz)};
    const double reach = chord_ * std::sqrt(sqr(magnitude(v[0])) + sqr(magnitude(v[1])) +
                                            sqr(magnitude(v[2])));
    Interval w[3];
    for (int i = 0; i < 3; ++i) {
      Interval s{0.0, 0.0};
      for (int j = 0; j < 3; ++j) s = add(s, mul(rot_[i][j], v[j]));
      w[i] = {s.lo - reach, s.hi + reach};
    }
    return {add(w[0], pl_.tx), add(w[1], pl_.ty), add(w[2], pl_.tz)};
  }

 private:
  static double sqr(double a) { return a * a; }

  SuperquadricBox q_;
  PlacementBox pl_;
  Interval c_;
  double rot_[3][3];
  double chord_ = 0.0;
};

// sign(v)·|v|^e: the canonical surface's parametric form.
double signedPower(double v, double e) { return std::copysign(std::pow(std::fabs(v), e), v); }

}  // namespace

void partExtent(const PartBox& part, Vec3* lo, Vec3* hi, PartExtentOptions options) {
  const SuperquadricBox& q = part.params;
  const Interval a = q.a1, b = mul(q.a1, q.a2), c = mul(q.a1, q.a3);
  const ForwardMap forward(part);
  // The hull starts from the mid part's surface (true points of the family).
  Vec3 hullLo{INFINITY, INFINITY, INFINITY}, hullHi{-INFINITY, -INFINITY, -INFINITY};
  {
    const PlacedSuperquadric m = midpointPart(part);
    const SuperquadricParams& s = m.params;
    constexpr int kEta = 16, kOmega = 32;
    for (int i = 0; i <= kEta; ++i) {
      const double eta = -0.5 * kPi + kPi * i / kEta;
      for (int j = 0; j < kOmega; ++j) {
        const double omega = -kPi + 2.0 * kPi * j / kOmega;
        const double ce = signedPower(std::cos(eta), s.eps1);
        const Vec3 canonical{s.A() * ce * signedPower(std::cos(omega), s.eps2),
                             s.B() * ce * signedPower(std::sin(omega), s.eps2),
                             s.C() * signedPower(std::sin(eta), s.eps1)};
        const Vec3 w = m.toWorld(canonical);
        if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z))) continue;
        hullLo = componentMin(hullLo, w);
        hullHi = componentMax(hullHi, w);
      }
    }
  }
  const auto within = [&](const Box3& w) {
    return w.x.lo >= hullLo.x && w.y.lo >= hullLo.y && w.z.lo >= hullLo.z && w.x.hi <= hullHi.x &&
           w.y.hi <= hullHi.y && w.z.hi <= hullHi.z;
  };
  const auto join = [&](const Box3& w) {
    hullLo = componentMin(hullLo, {w.x.lo, w.y.lo, w.z.lo});
    hullHi = componentMax(hullHi, {w.x.hi, w.y.hi, w.z.hi});
  };
  // No θ has a canonical point in the cell: G > 1 at its nearest corner with the smallest
  // exponents and the largest half-lengths (G increases in each ratio and exponent).
  SuperquadricParams unit;
  unit.eps1 = q.eps1.lo;
  unit.eps2 = q.eps2.lo;
  const auto empty = [&](const Box3& cell) {
    const Vec3 nearest{mignitude(cell.x) / a.hi, mignitude(cell.y) / b.hi,
                       mignitude(cell.z) / c.hi};
    return homogeneousInsideOutside(unit, nearest) > 1.0 + 1e-12;
  };
  const double across = 0.5 * std::max(options.cells, 1);
  const Vec3 finest{a.hi / across, b.hi / across, c.hi / across};
  // The turn across a unit of height, in finest cross-section cells: twist |t|/C and bend |kv|
  // (radians per unit length) times the largest radius of a cross-section (taper included).
  const double radius = std::hypot(a.hi * (1.0 + magnitude(q.kx)), b.hi * (1.0 + magnitude(q.ky)));
  const double turnPerHeight =
      (magnitude(q.t) / c.lo + magnitude(q.kv)) * radius / std::min(finest.x, finest.y);
  std::vector<Box3> stack{{{-a.hi, a.hi}, {-b.hi, b.hi}, {-c.hi, c.hi}}};
  int tested = 0;
  while (!stack.empty()) {
    const Box3 cell = stack.back();
    stack.pop_back();
    if (tested++ >= options.budget) {  // out of budget: the open cells' images, whole
      join(forward(cell));
      continue;
    }
    if (empty(cell)) continue;
    const Box3 image = forward(cell);
    if (within(image)) continue;
    // A cell's height counts also for the turn that the twist and the bend give across it:
    // turned by θ, the cell's image moves by about θ·radius, the span a cross-section cell may
    // have.
    const double rx = width(cell.x) / finest.x, ry = width(cell.y) / finest.y,
                 rz = width(cell.z) / finest.z + turnPerHeight * width(cell.z);
    const double widest = std::max({rx, ry, rz});
    if (widest <= 1.0 + 1e-9) {
      join(image);
      continue;
    }
    Box3 first = cell, second = cell;
    Interval& f = widest == rx ? first.x : widest == ry ? first.y : first.z;
    Interval& s = widest == rx ? second.x : widest == ry ? second.y : second.z;
    const double m = mid(f);
    f.hi = m;
    s.lo = m;
    stack.push_back(second);
    stack.push_back(first);
  }
  const Vec3 pad = (hullHi - hullLo) * 1e-9;
  *lo = hullLo - pad;
  *hi = hullHi + pad;
}

}  // namespace fsdb
