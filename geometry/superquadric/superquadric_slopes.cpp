#include "geometry/superquadric/superquadric_slopes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/transform.h"

namespace fsdb {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 2.71828182845904523536;

Interval expI(const Interval& a) { return {std::exp(a.lo), std::exp(a.hi)}; }
Interval logI(const Interval& a) { return {std::log(a.lo), std::log(a.hi)}; }  // a.lo > 0

// A value with its slopes over the boxes: v ⊇ {f}, d[j] ⊇ {∂f/∂θ_slots[j]}.
struct Ad {
  Interval v;
  Interval d[kPartSlots];
};

// The forward-mode rules (chain rule, each factor an interval over the boxes). `ok` turns false
// when a result leaves the tame range or a rule's precondition fails; the caller then gives up.
class Diff {
 public:
  explicit Diff(int n) : n_(n) {}
  bool ok() const { return ok_; }
  void fail() { ok_ = false; }

  Ad constant(const Interval& v) const {
    Ad a;
    a.v = v;
    for (int j = 0; j < n_; ++j) a.d[j] = {0.0, 0.0};
    return a;
  }
  Ad add(const Ad& a, const Ad& b) {
    Ad r;
    r.v = fsdb::add(a.v, b.v);
    for (int j = 0; j < n_; ++j) r.d[j] = fsdb::add(a.d[j], b.d[j]);
    return check(r);
  }
  Ad sub(const Ad& a, const Ad& b) {
    Ad r;
    r.v = fsdb::sub(a.v, b.v);
    for (int j = 0; j < n_; ++j) r.d[j] = fsdb::sub(a.d[j], b.d[j]);
    return check(r);
  }
  Ad addConstant(double c, const Ad& a) {
    Ad r = a;
    r.v = {a.v.lo + c, a.v.hi + c};
    return check(r);
  }
  Ad scale(double c, const Ad& a) {
    Ad r;
    r.v = fsdb::mul(c, a.v);
    for (int j = 0; j < n_; ++j) r.d[j] = fsdb::mul(c, a.d[j]);
    return check(r);
  }
  Ad mul(const Ad& a, const Ad& b) {  // d(ab) = a·db + b·da
    Ad r;
    r.v = fsdb::mul(a.v, b.v);
    for (int j = 0; j < n_; ++j) r.d[j] = fsdb::add(fsdb::mul(a.d[j], b.v), fsdb::mul(a.v, b.d[j]));
    return check(r);
  }
  Ad div(const Ad& a, const Ad& b) {  // d(a/b) = (da − (a/b)·db)/b, b away from 0
    if (contains(b.v, 0.0)) return failed();
    const Interval inverse{1.0 / b.v.hi, 1.0 / b.v.lo};  // 1/y decreases away from 0
    Ad r;
    r.v = fsdb::mul(a.v, inverse);
    for (int j = 0; j < n_; ++j)
      r.d[j] = fsdb::mul(fsdb::sub(a.d[j], fsdb::mul(r.v, b.d[j])), inverse);
    return check(r);
  }
  Ad sin(const Ad& a) { return chain(fsdb::sin(a.v), fsdb::cos(a.v), a); }
  Ad cos(const Ad& a) { return chain(fsdb::cos(a.v), neg(fsdb::sin(a.v)), a); }
  Ad hypot(const Ad& a, const Ad& b) {  // d|(a, b)| = (a·da + b·db)/|(a, b)|, away from 0
    const Interval h = fsdb::hypot(a.v, b.v);
    if (!(h.lo > 0.0)) return failed();
    Ad r;
    r.v = h;
    const Interval inverse{1.0 / h.hi, 1.0 / h.lo};
    for (int j = 0; j < n_; ++j)
      r.d[j] = fsdb::mul(fsdb::add(fsdb::mul(a.v, a.d[j]), fsdb::mul(b.v, b.d[j])), inverse);
    return check(r);
  }
  // atanc(t) = atan(t)/t (interval_functions.h), for the inverse bend's z' = (z/u)·atanc(kv·z/u):
  // written so, the slope of z' in kv has no cancellation (atan(kv·w)/kv has two large terms
  // that nearly cancel, and as intervals the kv slope straddled 0 at every band point of a bent
  // part).
  Ad atanc(const Ad& t) { return chain(fsdb::atanc(t.v), atancSlope(t.v), t); }
  // |x|: where x may change sign the slope is ±dx (either one-sided derivative).
  Ad abs(const Ad& a) {
    if (a.v.lo >= 0.0) return a;
    if (a.v.hi <= 0.0) return scale(-1.0, a);
    Ad r;
    r.v = fsdb::abs(a.v);
    for (int j = 0; j < n_; ++j) {
      const double m = magnitude(a.d[j]);
      r.d[j] = {-m, m};
    }
    return r;
  }
  // x^e for x >= 0, e > 0: d(x^e) = e·x^(e−1)·dx + x^e·ln x·de.
  Ad pow(const Ad& x, const Ad& e) {
    if (!(x.v.lo >= 0.0 && e.v.lo > 0.0)) return failed();
    Ad r;
    r.v = fsdb::pow(x.v, e.v);
    Interval cx, ce;  // the factors of dx and de
    bool xSlopes = false;
    for (int j = 0; j < n_; ++j) xSlopes = xSlopes || !isPoint(x.d[j], 0.0);
    if (x.v.lo > 0.0) {
      const Interval lx = logI(x.v);
      cx = fsdb::mul(e.v, expI(fsdb::mul(fsdb::sub(e.v, {1.0, 1.0}), lx)));
      ce = fsdb::mul(r.v, lx);
    } else {
      // x reaches 0. x^(e−1) <= max(1, X^(e.hi − 1)) on [0, X] when e >= 1 (unbounded below 1).
      const double X = x.v.hi;
      if (e.v.lo >= 1.0) {
        cx = fsdb::mul(e.v, {0.0, X > 1.0 ? std::pow(X, e.v.hi - 1.0) : 1.0});
      } else if (xSlopes) {
        return failed();
      } else {
        cx = {0.0, 0.0};  // dx = 0: the term vanishes
      }
      // x^e·ln x on [0, X]: its minimum over x > 0 is −1/(ℯ·e) (at x = ℯ^(−1/e)), the most
      // negative for the smallest e; for x <= 1 it is <= 0, beyond 1 it grows with x and e.
      ce = {-1.0 / (kE * e.v.lo), X > 1.0 ? std::pow(X, e.v.hi) * std::log(X) : 0.0};
    }
    if (!isTame(cx) || !isTame(ce)) return failed();
    for (int j = 0; j < n_; ++j)
      r.d[j] = fsdb::add(xSlopes ? fsdb::mul(cx, x.d[j]) : Interval{0.0, 0.0},
                         fsdb::mul(ce, e.d[j]));
    return check(r);
  }

 private:
  Ad chain(const Interval& value, const Interval& derivative, const Ad& a) {
    Ad r;
    r.v = value;
    for (int j = 0; j < n_; ++j) r.d[j] = fsdb::mul(derivative, a.d[j]);
    return check(r);
  }
  Ad check(const Ad& r) {
    bool good = isTame(r.v);
    for (int j = 0; j < n_ && good; ++j) good = isTame(r.d[j]);
    if (!good) ok_ = false;
    return r;
  }
  Ad failed() {
    ok_ = false;
    return constant({0.0, 0.0});
  }

  int n_;
  bool ok_ = true;
};

}  // namespace

PlacedSuperquadric partFromSlots(const Vec3& axis, const double (&v)[kPartSlots]) {
  PlacedSuperquadric part;
  part.params = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]};
  part.placement.translate = {v[9], v[10], v[11]};
  part.placement.axis = axis;
  part.placement.deg = v[12];
  part.placement.scale = v[13];
  return part;
}

bool insideOutsideSlopes(const PartBox& part, const Interval& x, const Interval& y,
                         const Interval& z, const int* slots, int count, Interval* out) {
  Diff D(count);
  Ad v[kPartSlots];
  for (int i = 0; i < kPartSlots; ++i) v[i] = D.constant(partSlot(part, i));
  for (int j = 0; j < count; ++j) v[slots[j]].d[j] = {1.0, 1.0};
  const Ad &eps1 = v[0], &eps2 = v[1], &a1 = v[2], &a2 = v[3], &a3 = v[4], &kx = v[5],
           &ky = v[6], &kv = v[7], &t = v[8], &deg = v[12], &scale = v[13];
  const auto differentiated = [&](int slot) {
    for (int j = 0; j < count; ++j)
      if (slots[j] == slot) return true;
    return false;
  };
  // World -> local (transform.h): Rᵀ(w − translate)/scale, with Rodrigues' formula
  //   Rᵀv = cos φ·v − sin φ·(k × v) + (1 − cos φ)(k·v)·k   (unit axis k, φ in radians).
  const Ad w[3] = {D.sub(D.constant(x), v[9]), D.sub(D.constant(y), v[10]),
                   D.sub(D.constant(z), v[11])};
  Ad local[3];
  if (isPoint(deg.v, deg.v.lo) && !differentiated(12)) {
    const Rotation r = Rotation::fromAxisAngle(part.placement.axis, deg.v.lo);
    const Vec3 cx = r.applyInverse({1, 0, 0}), cy = r.applyInverse({0, 1, 0}),
               cz = r.applyInverse({0, 0, 1});
    const double m[3][3] = {{cx.x, cy.x, cz.x}, {cx.y, cy.y, cz.y}, {cx.z, cy.z, cz.z}};
    for (int i = 0; i < 3; ++i)
      local[i] = D.add(D.add(D.scale(m[i][0], w[0]), D.scale(m[i][1], w[1])), D.scale(m[i][2], w[2]));
  } else {
    const Vec3 k = part.placement.axis / norm(part.placement.axis);
    const Ad phi = D.scale(kPi / 180.0, deg);
    const Ad c = D.cos(phi), s = D.sin(phi), oneMinusC = D.addConstant(1.0, D.scale(-1.0, c));
    const Ad kw = D.add(D.add(D.scale(k.x, w[0]), D.scale(k.y, w[1])), D.scale(k.z, w[2]));
    const Ad cross[3] = {D.sub(D.scale(k.y, w[2]), D.scale(k.z, w[1])),
                         D.sub(D.scale(k.z, w[0]), D.scale(k.x, w[2])),
                         D.sub(D.scale(k.x, w[1]), D.scale(k.y, w[0]))};
    const double kc[3] = {k.x, k.y, k.z};
    for (int i = 0; i < 3; ++i)
      local[i] = D.add(D.sub(D.mul(c, w[i]), D.mul(s, cross[i])),
                       D.mul(oneMinusC, D.scale(kc[i], kw)));
  }
  for (Ad& l : local) l = D.div(l, scale);
  if (!D.ok()) return false;
  // Inverse bend (deformation.cpp): with u = 1 − kv·x, v = kv·z, s = |(u, v)|,
  //   x' = (x(1 + u) − v·z)/(1 + s),  z' = atan2(v, u)/kv = atan(v/u)/kv for u > 0.
  Ad px = local[0], py = local[1], pz = local[2];
  if (!isPoint(kv.v, 0.0)) {
    if (contains(kv.v, 0.0)) return false;
    const Ad u = D.addConstant(1.0, D.scale(-1.0, D.mul(kv, px)));
    if (!(u.v.lo > 0.0)) return false;
    const Ad bv = D.mul(kv, pz);
    const Ad s = D.hypot(u, bv);
    const Ad bx = D.div(D.sub(D.mul(px, D.addConstant(1.0, u)), D.mul(bv, pz)), D.addConstant(1.0, s));
    pz = D.mul(D.div(pz, u), D.atanc(D.div(bv, u)));  // atan(kv·z/u)/kv
    px = bx;
  }
  const Ad C = D.mul(a1, a3);
  // Inverse twist: turn (x, y) back by θ = t·z/C.
  if (!isPoint(t.v, 0.0)) {
    const Ad theta = D.mul(t, D.div(pz, C));
    const Ad c = D.cos(theta), s = D.sin(theta);
    const Ad tx = D.add(D.mul(c, px), D.mul(s, py));
    py = D.sub(D.mul(c, py), D.mul(s, px));
    px = tx;
  }
  // Inverse taper: x/(kx·z/C + 1), y/(ky·z/C + 1).
  if (!isPoint(kx.v, 0.0) || !isPoint(ky.v, 0.0)) {
    const Ad zc = D.div(pz, C);
    px = D.div(px, D.addConstant(1.0, D.mul(kx, zc)));
    py = D.div(py, D.addConstant(1.0, D.mul(ky, zc)));
  }
  if (!D.ok()) return false;
  // docs/api.md §2 / Zhang, Pham & Chen, eq. 1:
  // F = (X^(2/eps2) + Y^(2/eps2))^(eps2/eps1) + Z^(2/eps1).
  const Ad X = D.div(D.abs(px), a1), Y = D.div(D.abs(py), D.mul(a1, a2)), Z = D.div(D.abs(pz), C);
  const Ad two = D.constant({2.0, 2.0});
  const Ad q2 = D.div(two, eps2), q1 = D.div(two, eps1), r = D.div(eps2, eps1);
  const Ad F = D.add(D.pow(D.add(D.pow(X, q2), D.pow(Y, q2)), r), D.pow(Z, q1));
  if (!D.ok()) return false;
  for (int j = 0; j < count; ++j) out[j] = F.d[j];
  return true;
}

// With any centre c of the box, the mean value theorem along the segment from c to θ (it stays in
// the box, which is convex, and F is Lipschitz along it, the slopes holding its one-sided
// derivatives at kinks) gives F(θ) ∈ F(c) + Σ_j D_j·(θ_j − c_j) for every θ of the box; the
// unlisted values are equal in θ and c. Every c is sound; the bound depends on c. For the lower
// end the term D_j·[a − c, b − c] (D_j = [dl, dh], θ_j ∈ [a, b]) has lower end
// min(dl·(b − c), dh·(a − c)) when dl < 0 < dh, largest where the two meet,
// c = (dh·a − dl·b)/(dh − dl); c = a where dl >= 0 and c = b where dh <= 0 (the term is then >= 0:
// the monotone corner). The upper end is the mirror image, c = (dh·b − dl·a)/(dh − dl). The
// midpoint centre is up to twice as wide in each value whose slope straddles 0.
double meanValueEnd(const PartBox& part, const Vec3& p, bool lower, const int* slots, int count,
                    const Interval* d) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double trivial = lower ? -kInf : kInf;
  double c[kPartSlots];
  bool listed[kPartSlots] = {};
  for (int j = 0; j < count; ++j) listed[slots[j]] = true;
  for (int i = 0; i < kPartSlots; ++i) {
    const Interval& v = partSlot(part, i);
    if (!listed[i] && v.lo != v.hi) return trivial;
    c[i] = v.lo;
  }
  for (int j = 0; j < count; ++j) {
    const Interval& v = partSlot(part, slots[j]);
    const double dl = d[j].lo, dh = d[j].hi;
    double centre;
    if (dl >= 0.0)
      centre = lower ? v.lo : v.hi;
    else if (dh <= 0.0)
      centre = lower ? v.hi : v.lo;
    else
      centre = lower ? (dh * v.lo - dl * v.hi) / (dh - dl) : (dh * v.hi - dl * v.lo) / (dh - dl);
    c[slots[j]] = std::isfinite(centre) ? std::min(std::max(centre, v.lo), v.hi) : mid(v);
  }
  double end = partFromSlots(part.placement.axis, c).insideOutside(p);
  for (int j = 0; j < count; ++j) {
    const Interval& v = partSlot(part, slots[j]);
    const double cj = c[slots[j]];
    const Interval term = mul(d[j], Interval{v.lo - cj, v.hi - cj});
    end += lower ? term.lo : term.hi;
  }
  return std::isfinite(end) ? end : trivial;
}

}  // namespace fsdb
