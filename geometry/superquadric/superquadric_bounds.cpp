#include "geometry/superquadric/superquadric_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/transform.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kMaxFinite = std::numeric_limits<double>::max();
constexpr double kInf = std::numeric_limits<double>::infinity();
const Interval kOne{1.0, 1.0};

struct IntervalVec3 {
  Interval x, y, z;
};

Interval point(double v) { return {v, v}; }

// World -> local: Rᵀ·(w − translate)/scale (transform.h), over the placement box. All
// rotations share the unit axis k, so R(θ)ᵀ = R(α)·R(θm)ᵀ with α = θm − θ for the mid angle
// θm: rotate the box by the crisp R(θm)ᵀ to w', then bound the turn by α, |α| <= δ (the half
// width), with Rodrigues' formula R(α)w' − w' = (cos α − 1)·w'⊥ + sin α·(k × w'):
//   |coordinate i of the change| <= (1 − cos δ)·|w'| + sin δ·|(k × w')_i|   (sin δ -> 1 past π/2).
// First order in δ, and scaled by the distance from the axis rather than by |w'|.
IntervalVec3 unplace(const PlacementBox& pl, const IntervalVec3& w) {
  const IntervalVec3 v{sub(w.x, pl.tx), sub(w.y, pl.ty), sub(w.z, pl.tz)};
  const Interval inverseScale{1.0 / pl.scale.hi, 1.0 / pl.scale.lo};
  if (isPoint(pl.deg, 0.0))  // unrotated parts are common: skip the matrix
    return {mul(v.x, inverseScale), mul(v.y, inverseScale), mul(v.z, inverseScale)};
  const Rotation r = Rotation::fromAxisAngle(pl.axis, mid(pl.deg));
  // Rᵀv = v.x·Rᵀe_x + v.y·Rᵀe_y + v.z·Rᵀe_z.
  const Vec3 cx = r.applyInverse({1, 0, 0}), cy = r.applyInverse({0, 1, 0}),
             cz = r.applyInverse({0, 0, 1});
  IntervalVec3 u{add(add(mul(cx.x, v.x), mul(cy.x, v.y)), mul(cz.x, v.z)),
                 add(add(mul(cx.y, v.x), mul(cy.y, v.y)), mul(cz.y, v.z)),
                 add(add(mul(cx.z, v.x), mul(cy.z, v.y)), mul(cz.z, v.z))};
  const double delta = std::min(0.5 * (pl.deg.hi - pl.deg.lo) * kDegToRad, kPi);
  if (delta > 0.0) {
    const Vec3 k = pl.axis / norm(pl.axis);
    const double radial = (1.0 - std::cos(delta)) *
                          std::hypot(magnitude(u.x), magnitude(u.y), magnitude(u.z));
    const double sinBound = delta >= 0.5 * kPi ? 1.0 : std::sin(delta);
    // k × w' over the box, coordinate by coordinate.
    const double kw[3] = {magnitude(sub(mul(k.y, u.z), mul(k.z, u.y))),
                          magnitude(sub(mul(k.z, u.x), mul(k.x, u.z))),
                          magnitude(sub(mul(k.x, u.y), mul(k.y, u.x)))};
    const auto widen = [&](const Interval& a, double kwi) {
      const double pad = radial + sinBound * kwi;
      return Interval{a.lo - pad, a.hi + pad};
    };
    u = {widen(u.x, kw[0]), widen(u.y, kw[1]), widen(u.z, kw[2])};
  }
  return {mul(u.x, inverseScale), mul(u.y, inverseScale), mul(u.z, inverseScale)};
}

// Inverse bend (deformation.cpp, unbend) over intervals. With u = 1 − kX, v = kZ, s = |(u, v)|:
//   x = (X(1 + u) − vZ)/(1 + s)   (the cancellation-free form of (1 − s)/k, valid for all k),
//   z = (Z/u)·atanc(v/u) for u > 0,  z = atan2(v, u)/k otherwise.
// Neither divides by an interval k that may hold 0. Every point also obeys
//   |z| <= max(π|X|, 2|Z|):
// for u <= 0, |γ| <= π and |kX| >= 1; for 0 < u <= 1/2, |γ| < π/2 and |kX| >= 1/2; for
// u > 1/2, |z| = |atan(v/u)/k| <= |Z|/u < 2|Z|. That bound holds even where the box
// straddles the bending axis (u and v both hold 0), where the formulas above give nothing.
IntervalVec3 unbend(const Interval& k, const IntervalVec3& p) {
  if (isPoint(k, 0.0)) return p;
  const Interval u = sub(kOne, mul(k, p.x));
  const Interval v = mul(k, p.z);
  const Interval s = hypot(u, v);
  const Interval x = div(sub(mul(p.x, add(kOne, u)), mul(v, p.z)), add(kOne, s));
  const double m = std::max(kPi * magnitude(p.x), 2.0 * magnitude(p.z));
  Interval z{-m, m};
  // Reciprocals of values above 1/kTame stay tame, so the products below stay finite.
  const Interval ak = abs(k);
  if (u.lo >= 1.0 / kTame) {
    const Interval w = div(v, u);
    z = intersect(z, mul(div(p.z, u), atanc(w)));
    // The same z as atan(v/u)/k: where k keeps away from 0 this keeps the correlation between
    // Z/u and atanc(v/u) that the product above loses (both are large together when u is
    // small), e.g. for points near the bending axis. atan is increasing: its range is its ends.
    if (ak.lo >= 1.0 / kTame) z = intersect(z, div({std::atan(w.lo), std::atan(w.hi)}, k));
  }
  if (u.lo < 1.0 / kTame && ak.lo >= 1.0 / kTame) z = intersect(z, div(atan2(v, u), k));
  return {x, p.y, z};
}

// Inverse twist (deformation.cpp, untwist): rotate (X, Y) back by θ = t·Z/C. Two sound
// enclosures, intersected:
//  * interval cos θ and sin θ in x = cX + sY, y = cY − sX;
//  * the crisp turn by the mid angle θm, then the change of a turn by α, |α| <= δ, in the
//    plane: |Δx| <= (1 − cos δ)·r + sin δ·|y'|, |Δy| <= (1 − cos δ)·r + sin δ·|x'| (as in
//    unplace), tighter where the products of the first form do not cancel.
// A turn keeps r = |(x, y)|, which bounds each coordinate when θ spans much of a turn.
IntervalVec3 untwist(const Interval& t, const Interval& c, const IntervalVec3& p) {
  if (isPoint(t, 0.0)) return p;
  const Interval zc = div(p.z, c);
  // An infinite z/C (a tiny C) leaves θ unknown: the full turn.
  const Interval theta =
      std::isfinite(zc.lo) && std::isfinite(zc.hi) ? mul(t, zc) : Interval{-kInf, kInf};
  Interval x = p.x, y = p.y;
  turnEnclosure(neg(theta), &x, &y);  // back by θ
  return {x, y, p.z};
}

// |x / f| for the taper factor f = k·z/C + 1 (deformation.cpp, untaper). Only |x| matters to
// F, so the sign of f (negative only outside the part, |z| > C) drops out. Where f may
// vanish the crisp quotient is ±∞ (0 for x = 0): the upper end is then ∞.
Interval absUntaper(const Interval& x, const Interval& k, const Interval& zc) {
  const Interval ax = abs(x);
  if (isPoint(k, 0.0)) return ax;
  if (ax.hi == 0.0) return ax;
  const Interval af = std::isfinite(zc.lo) && std::isfinite(zc.hi) ? abs(add(mul(k, zc), kOne))
                                                                   : Interval{0.0, kInf};
  const double lo = af.hi == 0.0 ? (ax.lo > 0.0 ? kInf : 0.0) : ax.lo / af.hi;
  const double hi = af.lo == 0.0 ? kInf : ax.hi / af.lo;
  return {lo, hi};
}

// The box of canonical |x|/A, |y|/B, |z|/C over the point and parameter boxes: the inputs of
// the canonical F, which increases in each. Returns false when intermediate values leave
// the tame range (absurd coordinates or sizes); the caller then answers the trivial bound.

// A lower bound of the cross-section norm R = ||(X, Y)||_(2/eps2) that the twist cannot blur:
// the twist turns (x, y) about z and keeps its radius r, and with M >= A·|fx|, B·|fy| (the taper
// factors f) X >= |x'|/M and Y >= |y'|/M, so |(X, Y)| >= r/M; a q-norm of two values is at least
// their 2-norm for q <= 2 and at least 2^(1/q − 1/2) times it for q > 2 (power means). Interval
// twists of a wide z spin the box of (x', y') and lose its distance from the axis; this keeps it.
double radialLowerBound(const SuperquadricBox& q, const IntervalVec3& unbent, const Interval& zc) {
  const double r = std::hypot(mignitude(unbent.x), mignitude(unbent.y));
  if (!(r > 0.0)) return 0.0;
  const auto factor = [&](const Interval& k) {
    if (isPoint(k, 0.0)) return 1.0;
    if (!(std::isfinite(zc.lo) && std::isfinite(zc.hi))) return kInf;
    return magnitude(add(mul(k, zc), kOne));
  };
  const double m = std::max(q.a1.hi * factor(q.kx), q.a1.hi * q.a2.hi * factor(q.ky));
  if (!(m > 0.0 && std::isfinite(m))) return 0.0;
  const double qMax = 2.0 / q.eps2.lo;
  const double norm = qMax <= 2.0 ? 1.0 : std::pow(2.0, 1.0 / qMax - 0.5);
  return norm * r / m;
}

bool canonicalRatios(const PartBox& part, const IntervalVec3& world, IntervalVec3* ratios,
                     double* radialLo) {
  const SuperquadricBox& q = part.params;
  const PlacementBox& pl = part.placement;
  // Half-lengths (superquadric.h): A = a1, B = a1·a2, C = a1·a3, all positive.
  const Interval a = q.a1, b = mul(q.a1, q.a2), c = mul(q.a1, q.a3);
  constexpr double kSmall = 1.0 / kTame;  // reciprocals of larger values stay tame
  if (!(isTame(world.x) && isTame(world.y) && isTame(world.z) && isTame(pl.tx) &&
        isTame(pl.ty) && isTame(pl.tz) && pl.scale.lo >= kSmall && a.lo >= kSmall &&
        b.lo >= kSmall && c.lo >= kSmall))
    return false;
  const IntervalVec3 local = unplace(pl, world);
  if (!isTame(local.x) || !isTame(local.y) || !isTame(local.z)) return false;
  const double reach = std::max({magnitude(local.x), magnitude(local.y), magnitude(local.z)});
  if (!(magnitude(q.kv) * reach <= kTame)) return false;
  const IntervalVec3 unbent = unbend(q.kv, local);
  const IntervalVec3 p = untwist(q.t, c, unbent);
  const Interval zc = div(p.z, c);
  *ratios = {div(absUntaper(p.x, q.kx, zc), a), div(absUntaper(p.y, q.ky, zc), b),
             div(abs(p.z), c)};
  *radialLo = isPoint(q.t, 0.0) ? 0.0 : radialLowerBound(q, unbent, zc);
  return true;
}

// G at one corner of the ratio box with the given exponents: the crisp homogeneous
// function with unit half-lengths (the ratios are already divided by them).
double unitG(double eps1, double eps2, double x, double y, double z) {
  SuperquadricParams unit;
  unit.eps1 = eps1;
  unit.eps2 = eps2;
  return homogeneousInsideOutside(unit, {x, y, z});
}

// G = ||(R, Z)||_(2/eps1) with R = ||(X, Y)||_(2/eps2) (superquadric.cpp). A p-norm of
// nonnegative values increases with them and decreases with p, so G increases in X, Y, Z,
// eps1 and eps2: its range over the box is the value at the low corner with the low eps and
// at the high corner with the high eps, exactly.
// G >= max(R, Z) >= R: radialLo (a lower bound of R) raises the lower end.
Interval gRange(const SuperquadricBox& q, const IntervalVec3& r, double radialLo) {
  const double hi = unitG(q.eps1.hi, q.eps2.hi, r.x.hi, r.y.hi, r.z.hi);
  return {std::min(std::max(unitG(q.eps1.lo, q.eps2.lo, r.x.lo, r.y.lo, r.z.lo), radialLo), hi), hi};
}

Interval saturate(const Interval& a) {
  return {std::min(a.lo, kMaxFinite), std::min(a.hi, kMaxFinite)};
}

}  // namespace

PlacedSuperquadric midpointPart(const PartBox& box) {
  PlacedSuperquadric part;
  const SuperquadricBox& q = box.params;
  part.params = {mid(q.eps1), mid(q.eps2), mid(q.a1), mid(q.a2), mid(q.a3),
                 mid(q.kx),   mid(q.ky),   mid(q.kv), mid(q.t)};
  const PlacementBox& pl = box.placement;
  part.placement.translate = {mid(pl.tx), mid(pl.ty), mid(pl.tz)};
  part.placement.axis = pl.axis;
  part.placement.deg = mid(pl.deg);
  part.placement.scale = mid(pl.scale);
  return part;
}

// Interval cos θ and sin θ in the turn, intersected with the disc the turn keeps and, for
// narrow θ, with the mid angle's turn widened by the change of a turn by at most δ (as unplace).
void turnEnclosure(const Interval& theta, Interval* x, Interval* y) {
  const double r = std::hypot(magnitude(*x), magnitude(*y));
  const Interval disc{-r, r};
  const Interval cs = cos(theta), sn = sin(theta);
  Interval tx = intersect(sub(mul(cs, *x), mul(sn, *y)), disc);
  Interval ty = intersect(add(mul(sn, *x), mul(cs, *y)), disc);
  const double delta = 0.5 * (theta.hi - theta.lo);
  if (delta < 0.5 * kPi) {  // also false for infinite or NaN ends
    const double m = mid(theta), cm = std::cos(m), sm = std::sin(m);
    const Interval xm = sub(mul(cm, *x), mul(sm, *y)), ym = add(mul(sm, *x), mul(cm, *y));
    const double radial = (1.0 - std::cos(delta)) * r, sd = std::sin(delta);
    const double px = radial + sd * magnitude(ym), py = radial + sd * magnitude(xm);
    tx = intersect(tx, {xm.lo - px, xm.hi + px});
    ty = intersect(ty, {ym.lo - py, ym.hi + py});
  }
  *x = tx;
  *y = ty;
}

PartBox crispPartBox(const PlacedSuperquadric& part) {
  const SuperquadricParams& p = part.params;
  const Placement& pl = part.placement;
  PartBox box;
  box.params = {point(p.eps1), point(p.eps2), point(p.a1), point(p.a2), point(p.a3),
                point(p.kx),   point(p.ky),   point(p.kv), point(p.t)};
  box.placement = {point(pl.translate.x), point(pl.translate.y), point(pl.translate.z),
                   pl.axis,               point(pl.deg),         point(pl.scale)};
  return box;
}

bool contains(const PartBox& box, const PlacedSuperquadric& part) {
  const SuperquadricBox& q = box.params;
  const SuperquadricParams& p = part.params;
  const PlacementBox& b = box.placement;
  const Placement& pl = part.placement;
  // Same axis direction: parallel (zero cross product) and pointing the same way.
  const bool sameAxis = norm(cross(b.axis, pl.axis)) <= 1e-15 * norm(b.axis) * norm(pl.axis) &&
                        dot(b.axis, pl.axis) > 0.0;
  return contains(q.eps1, p.eps1) && contains(q.eps2, p.eps2) && contains(q.a1, p.a1) &&
         contains(q.a2, p.a2) && contains(q.a3, p.a3) && contains(q.kx, p.kx) &&
         contains(q.ky, p.ky) && contains(q.kv, p.kv) && contains(q.t, p.t) &&
         contains(b.tx, pl.translate.x) && contains(b.ty, pl.translate.y) &&
         contains(b.tz, pl.translate.z) && sameAxis && contains(b.deg, pl.deg) &&
         contains(b.scale, pl.scale);
}

Interval insideOutsideBounds(const PartBox& part, const Interval& x, const Interval& y,
                             const Interval& z) {
  IntervalVec3 r;
  double radialLo = 0.0;
  if (!canonicalRatios(part, {x, y, z}, &r, &radialLo)) return {0.0, kMaxFinite};
  const SuperquadricBox& q = part.params;
  const Interval exponent{2.0 / q.eps1.hi, 2.0 / q.eps1.lo};  // 2/eps1
  // Two sound forms of F; they differ only where eps1 is an interval (both use it twice).
  //   F = G^(2/eps1)                                         (superquadric.cpp)
  //   F = R^(2/eps1) + Z^(2/eps1),  R = ||(X, Y)||_(2/eps2)   (Zhang, Pham & Chen, eq. 1)
  // R increases in X, Y and eps2, like G (gRange), so its range is two corner values.
  const Interval viaG = pow(gRange(q, r, radialLo), exponent);
  if (q.eps1.lo == q.eps1.hi) return viaG;  // one exponent: viaG is already the exact range
  const double rHi = unitG(q.eps1.hi, q.eps2.hi, r.x.hi, r.y.hi, 0.0);
  const Interval R{std::min(std::max(unitG(q.eps1.lo, q.eps2.lo, r.x.lo, r.y.lo, 0.0), radialLo), rHi),
                   rHi};
  const Interval viaSum = saturate(add(pow(R, exponent), pow(r.z, exponent)));
  return intersect(viaG, viaSum);
}

void deformedHalfExtents(const SuperquadricBox& q, double* X, double* Y, double* Z) {
  // Canonical half-lengths, widened by the taper factor (docs/api.md §2: X = x(kx·z/C + 1),
  // |z| <= C).
  double x = q.a1.hi * (1.0 + magnitude(q.kx));
  double y = q.a1.hi * q.a2.hi * (1.0 + magnitude(q.ky));
  double z = q.a1.hi * q.a3.hi;
  // Twist turns the cross-section about z: it stays within the circle of the corner radius.
  if (magnitude(q.t) > 0.0) x = y = std::hypot(x, y);
  // Bend with curvature k, γ = k·z: X' − x = (1/k − x)(1 − cos γ) and Z' = sin γ·(1/k − x).
  // With 1 − cos γ <= min(2, γ²/2) and |sin γ| <= min(1, |γ|):
  //   |X' − x| <= (1 + K·X)·min(2/|k|, |k|·Z²/2) <= (1 + K·X)·min(Z, K·Z²/2),
  //   |Z'| <= min(1/|k|, Z) + X·min(1, |k|·Z) <= Z + X·min(1, K·Z),   K = max |kv|.
  const double K = magnitude(q.kv);
  if (K > 0.0) {
    const double bentX = x + (1.0 + K * x) * std::min(z, 0.5 * K * z * z);
    const double bentZ = z + x * std::min(1.0, K * z);
    x = bentX;
    z = bentZ;
  }
  *X = x;
  *Y = y;
  *Z = z;
}

namespace {

// The same test one map further in, after the inverse bend (whose interval z blows up near the
// bending axis, where the taper factor then may vanish and the enclosure says nothing): F <= 1
// needs every canonical ratio <= 1 (Zhang, Pham & Chen, eq. 1: each term of F is >= 0), so
// |z| <= C, and the taper factors k·z/C + 1 lie in [1 − |k|, 1 + |k|]: the untwisted point has
// |x| <= A(1 + |kx|), |y| <= B(1 + |ky|), and the twist (a turn about z, z unchanged) keeps its
// radius. So an unbent box with |z| > C, or (untwisted) |x| or |y| beyond those, or (twisted) a
// radius beyond theirs, holds no point of any S(θ). Near the bending axis the unbent x is about
// 1/k, far beyond A: points there are excluded here while the whole-chain enclosure is trivial.
bool missesUnbentHull(const SuperquadricBox& q, const IntervalVec3& local) {
  if (isPoint(q.kv, 0.0)) return false;  // the test above already saw this box
  const double reach = std::max({magnitude(local.x), magnitude(local.y), magnitude(local.z)});
  if (!(magnitude(q.kv) * reach <= kTame)) return false;
  IntervalVec3 b = unbend(q.kv, local);
  // x = (1 − s)/k, the direct form of unbend's x (deformation.cpp), where k keeps away from 0:
  // near the bending axis s is small and this keeps x near 1/k, where the cancellation-free
  // form multiplies wide intervals.
  if (abs(q.kv).lo >= 1.0 / kTame) {
    const Interval s = hypot(sub(kOne, mul(q.kv, local.x)), mul(q.kv, local.z));
    b.x = intersect(b.x, div(sub(kOne, s), q.kv));
  }
  constexpr double kSlack = 1.0 + 1e-9;
  const double X = q.a1.hi * (1.0 + magnitude(q.kx)) * kSlack;
  const double Y = q.a1.hi * q.a2.hi * (1.0 + magnitude(q.ky)) * kSlack;
  const double Z = q.a1.hi * q.a3.hi * kSlack;
  if (mignitude(b.z) > Z) return true;  // (NaN compares false: no conclusion)
  if (isPoint(q.t, 0.0)) return mignitude(b.x) > X || mignitude(b.y) > Y;
  return std::hypot(mignitude(b.x), mignitude(b.y)) > std::hypot(X, Y);
}

}  // namespace

bool missesDeformedHull(const PartBox& part, const Interval& x, const Interval& y,
                        const Interval& z) {
  const PlacementBox& pl = part.placement;
  if (!(isTame(x) && isTame(y) && isTame(z) && isTame(pl.tx) && isTame(pl.ty) && isTame(pl.tz) &&
        pl.scale.lo >= 1.0 / kTame))
    return false;
  double e[3];
  deformedHalfExtents(part.params, &e[0], &e[1], &e[2]);
  const IntervalVec3 local = unplace(pl, {x, y, z});
  const Interval l[3] = {local.x, local.y, local.z};
  for (int i = 0; i < 3; ++i) {
    const double reach = e[i] * (1.0 + 1e-9);
    if (l[i].lo > reach || l[i].hi < -reach) return true;
  }
  return missesUnbentHull(part.params, local);
}

Interval homogeneousInsideOutsideBounds(const PartBox& part, const Interval& x,
                                        const Interval& y, const Interval& z) {
  IntervalVec3 r;
  double radialLo = 0.0;
  if (!canonicalRatios(part, {x, y, z}, &r, &radialLo)) return {0.0, kInf};
  return gRange(part.params, r, radialLo);
}

}  // namespace fsdb
