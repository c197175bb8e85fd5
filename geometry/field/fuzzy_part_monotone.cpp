// FuzzyPartField's shortcuts that need no search: the monotone corners (cornerLevels, with the
// signs of monotoneSigns) and the closed form of one fuzzy size (sizeLevels). See
// docs/design/fuzzy-part-field.md.
#include <algorithm>
#include <cmath>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/field/fuzzy_part_field_detail.h"
#include "geometry/superquadric/deformation.h"
#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/superquadric_slopes.h"

namespace fsdb {

using namespace part_field_detail;

namespace {

// Narrows [lo, hi] around the level where F at a corner moving with α crosses 1: on entry
// qualifies(value(lo)) and !qualifies(value(hi)), with qualifies(f) = f <= 1 (inside) or f > 1
// (!inside), value(α) monotone; on return the same holds and hi − lo <= tau. Secant steps through
// the two latest points (the corners move linearly in α between breakpoints, so they converge
// fast), kept τ/4 inside the bracket, halving after eight; when the next estimate lies within
// 0.45·τ of the last point, a probe τ/2 beyond it on that side usually closes the bracket.
template <typename Value>
void narrowBracket(const Value& value, bool inside, double tau, double* lo, double* hi, double fLo,
                   double fHi) {
  const auto qualifies = [inside](double f) { return inside ? f <= 1.0 : f > 1.0; };
  double a = *lo, fa = fLo, b = *hi, fb = fHi;  // the two latest points
  const auto secant = [&](double* r) {
    if (!(std::isfinite(fa) && std::isfinite(fb) && fa != fb)) return false;
    *r = b - (fb - 1.0) * (b - a) / (fb - fa);
    return std::isfinite(*r);
  };
  const auto take = [&](double t) {
    const double f = value(t);
    if (qualifies(f))
      *lo = t;
    else
      *hi = t;
    a = b;
    fa = fb;
    b = t;
    fb = f;
  };
  for (int k = 0; *hi - *lo > tau; ++k) {
    double t = 0.5 * (*lo + *hi), r;
    if (k < 8 && secant(&r) && r > *lo && r < *hi)
      t = std::min(std::max(r, *lo + 0.25 * tau), *hi - 0.25 * tau);
    if (!(t > *lo && t < *hi)) break;  // τ below the spacing of doubles near the bracket
    take(t);
    if (*hi - *lo > tau && secant(&r) && std::fabs(r - t) < 0.45 * tau) {
      const double q = r > t ? t + 0.5 * tau : t - 0.5 * tau;
      if (q > *lo && q < *hi) take(q);
    }
  }
}

}  // namespace

bool FuzzyPartField::monotoneSigns(const Vec3& lo, const Vec3& hi, signed char* sign) const {
  return monotoneSignsOver(support_, lo, hi, sign);
}

bool FuzzyPartField::monotoneSignsOver(const PartBox& box, const Vec3& lo, const Vec3& hi,
                                       signed char* sign) const {
  Interval d[kSlots];
  if (fuzzyCount_ == 0 ||
      !insideOutsideSlopes(box, {lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, fuzzySlots_,
                           fuzzyCount_, d))
    return false;
  for (int i = 0; i < kSlots; ++i) sign[i] = 0;
  for (int j = 0; j < fuzzyCount_; ++j) {
    if (d[j].lo >= 0.0)
      sign[fuzzySlots_[j]] = 1;
    else if (d[j].hi <= 0.0)
      sign[fuzzySlots_[j]] = -1;
    else
      return false;
  }
  return true;
}

PlacedSuperquadric FuzzyPartField::cornerAt(double alpha, const signed char* sign,
                                            bool least) const {
  double v[kSlots];
  for (int i = 0; i < kSlots; ++i) v[i] = slot(support_, i).lo;  // crisp values: lo == hi
  for (int j = 0; j < fuzzyCount_; ++j) {
    const int i = fuzzySlots_[j];
    const Interval c = alpha == 0.0   ? slot(support_, i)
                       : alpha == 1.0 ? slot(core_, i)
                                      : values_[i]->alphaCut(alpha);
    v[i] = (sign[i] > 0) == least ? c.lo : c.hi;
  }
  return thetaAt(support_, v);
}

float FuzzyPartField::roundedUpper(double level, const PlacedSuperquadric& witness) const {
  float u = floatDown(level);
  while (u > 0.0f && !contains(u == 1.0f ? core_ : cutAt(u), witness))
    u = std::nextafter(u, -1.0f);
  return u;
}

// The monotone shortcut. Where F is monotone in every fuzzy value over P(0) at p (signs certified
// by insideOutsideSlopes), moving one value at a time to the end that lowers F never raises it, so
//   g(α) = min{F(p; θ) : θ ∈ P(α)} = F(p; least corner of P(α)),
//   h(α) = max{F(p; θ) : θ ∈ P(α)} = F(p; largest corner of P(α)),
// exactly (P(α) ⊆ P(0) is a box). With θ ∈ P(α) ⇔ m(θ) >= α (α > 0), u_true = sup{α : g(α) <= 1}
// and l_true = inf{α : h(α) <= 1}; g rises and h falls with α (P(α) shrinks). So brackets
// [lo, hi] with g(lo) <= 1 < g(hi) hold u_true (u = lo, witness the least corner of P(lo)), and
// ones with h(lo) > 1 >= h(hi) hold l_true (l = hi, proven: the largest F over P(hi) is <= 1),
// each to τ: the guarantees of the search, with no budget to run out. g(0) > 1: no θ puts p
// inside (u = 0, never); h(0) <= 1: p ∈ lower(0) (l = 0); h(1) > 1: a θ of P(1) puts p outside.
AlphaLevels FuzzyPartField::cornerLevels(const Vec3& p, const signed char* sign,
                                         bool inCore) const {
  const double tau = options_.tolerance;
  AlphaLevels out;
  const auto least = [&](double a) { return valueAt(cornerAt(a, sign, true), p); };
  const double g0 = inCore ? 0.0 : least(0.0);
  if (g0 > 1.0) return {0.0f, kNeverInside};
  const double g1 = inCore ? 0.0 : least(1.0);
  if (g1 > 1.0) {
    double lo = 0.0, hi = 1.0;
    narrowBracket(least, true, tau, &lo, &hi, g0, g1);
    out.upper = roundedUpper(lo, cornerAt(lo, sign, true));
    return out;  // l <= 1 needs p ∈ lower(1) ⊆ upper(1)
  }
  out.upper = 1.0f;
  const auto largest = [&](double a) { return valueAt(cornerAt(a, sign, false), p); };
  const double h0 = largest(0.0);
  if (h0 <= 1.0) {
    out.lower = 0.0f;
    return out;
  }
  const double h1 = largest(1.0);
  if (h1 > 1.0) return out;  // never in lower(1)
  double lo = 0.0, hi = 1.0;
  narrowBracket(largest, false, tau, &lo, &hi, h0, h1);
  out.lower = floatUp(hi);
  return out;
}

// The monotone shortcut above a level. Where F is not monotone over all of P(0) at p, it often is
// over the smaller cut P(α) near the answer: a bend through 0 or a twist over a wide range swings
// F both ways at low levels only. The signs at the core guess the corners; the corner path then
// brackets the level as cornerLevels does, and the bracket needs only two facts to hold:
//  * its lower end is shown by a crisp θ (the corner of P(lo), F <= 1 for u, F > 1 for l), so
//    u_true >= lo and l_true >= lo whatever F does;
//  * its upper end hi is proven when F is monotone over P(hi) with the same signs (slopes over
//    P(hi) at p): then the corner is F's least (u) or largest (l) value over all of P(hi), so
//    g(hi) > 1 (no θ of P(hi) puts p inside: u_true < hi) or h(hi) <= 1 (every θ does:
//    l_true <= hi).
// So the answers carry cornerLevels' guarantees. Returns 0 when it cannot answer u, 1 when it
// answered u = 1 and not l (the caller searches l), 2 when *out holds both levels.
int FuzzyPartField::levelsAboveCut(const Vec3& p, AlphaLevels* out, Seed* up, Seed* down) const {
  const double tau = options_.tolerance;
  signed char sign[kSlots];
  // The guess: the signs of the slopes at the core's midpoint (a guess only: the bracket's ends
  // are shown and proven below whatever it is).
  {
    Interval d[kSlots];
    if (fuzzyCount_ == 0 || !insideOutsideSlopes(coreMidpoint_, {p.x, p.x}, {p.y, p.y},
                                                 {p.z, p.z}, fuzzySlots_, fuzzyCount_, d))
      return 0;
    for (int i = 0; i < kSlots; ++i) sign[i] = 0;
    for (int j = 0; j < fuzzyCount_; ++j) sign[fuzzySlots_[j]] = d[j].lo + d[j].hi >= 0.0 ? 1 : -1;
  }
  // Do the slopes over P(alpha) at p keep the core's signs?
  const auto provenAt = [&](double alpha) {
    signed char s[kSlots];
    if (!monotoneSignsOver(levelBox(alpha), p, p, s)) return false;
    for (int j = 0; j < fuzzyCount_; ++j)
      if (s[fuzzySlots_[j]] != sign[fuzzySlots_[j]]) return false;
    return true;
  };
  const auto least = [&](double a) { return valueAt(cornerAt(a, sign, true), p); };
  const double g1 = least(1.0);
  if (g1 > 1.0) {
    const double g0 = least(0.0);
    if (!(g0 <= 1.0)) return 0;  // no witness in P(0) on this path: the search decides
    double lo = 0.0, hi = 1.0;
    narrowBracket(least, true, tau, &lo, &hi, g0, g1);
    if (!provenAt(hi)) {
      *up = {lo, cornerAt(lo, sign, true)};
      return 0;
    }
    *out = {roundedUpper(lo, cornerAt(lo, sign, true)), kNeverInside};
    return 2;  // l <= 1 needs p ∈ lower(1) ⊆ upper(1)
  }
  // u = 1: the least corner of P(1) is a witness.
  out->upper = 1.0f;
  const auto largest = [&](double a) { return valueAt(cornerAt(a, sign, false), p); };
  const double h1 = largest(1.0);
  if (h1 > 1.0) {  // a θ of P(1) puts p outside: never in lower(1)
    out->lower = kNeverInside;
    return 2;
  }
  const double h0 = largest(0.0);
  if (!(h0 > 1.0)) return 1;  // l = 0 needs a proof over all of P(0): the search's
  double lo = 0.0, hi = 1.0;
  narrowBracket(largest, false, tau, &lo, &hi, h0, h1);
  if (!provenAt(hi)) {
    *down = {lo, cornerAt(lo, sign, false)};
    return 1;
  }
  out->lower = floatUp(hi);
  return 2;
}

// One fuzzy size v (a1, which scales A, B and C together, or the placement scale) and no
// taper, twist or bend: F(p; v) = (ρ/v)^(2/ε1) with ρ = v_ref·G(p; v_ref), G = F^(ε1/2)
// (docs/api.md §2: the canonical ratios scale with 1/v), so S(v) holds p exactly when v >= ρ.
// Then, with μ̂ the hull membership of v (rising up to the core, falling after it), exactly:
//   u = 1 for ρ <= core.hi, μ̂(ρ) on the falling side, 0 (and l = never) beyond the support;
//   l = 0 for ρ <= support.lo, μ̂(ρ) on the rising side, never for ρ > core.lo.
// One evaluation of G gives ρ. Each answer rests on the corner that the monotone shortcut would
// have evaluated (the F-lowering end of P(u) for u, the F-raising end of P(l) for l): F there is
// (ρ/v)^(2/ε1), decided by the identity where v is clear of ρ by a relative 1e-9 (far above the
// rounding of ρ), else by a crisp evaluation of F at that corner. So the answers carry the witnesses
// and proofs of cornerLevels, rounded the same way (u down, l up), and are exact rather than
// τ-brackets. False where a check disagrees (rounding at the boundary, overflow): the caller
// falls back to the general path.
bool FuzzyPartField::sizeLevels(const Vec3& p, AlphaLevels* out) const {
  // G = F^(ε1/2) (superquadric.h) is homogeneous of degree −1 in v: G(p; v) = G(p; v_ref)·v_ref/v,
  // so S(v) holds p exactly when v >= ρ = v_ref·G(p; v_ref). (sizeSlot_ is set only when every
  // value but v is crisp, so the angle is crisp and rotation_ is built.)
  const PlacedSuperquadric& reference = sizeReferencePart_;
  const Placement& pl = reference.placement;
  const Vec3 local = rotation_.applyInverse(p - pl.translate) / pl.scale;
  const double rho =
      sizeReference_ * homogeneousInsideOutside(reference.params, undeformPoint(reference.params, local));
  if (!std::isfinite(rho)) return false;
  const FuzzyNumber& v = *values_[sizeSlot_];
  const Interval support = slot(support_, sizeSlot_), core = slot(core_, sizeSlot_);
  // Does S(value) hold p? By the identity (value >= ρ) where value is clear of ρ by far more than
  // rounding, else by a crisp evaluation of F at that value.
  constexpr double kClear = 1e-9;
  const auto inside = [&](double value) {
    if (value >= rho * (1.0 + kClear)) return true;
    if (value <= rho * (1.0 - kClear)) return false;
    double theta[kSlots];
    for (int i = 0; i < kSlots; ++i) theta[i] = slot(support_, i).lo;
    theta[sizeSlot_] = value;
    return valueAt(thetaAt(support_, theta), p) <= 1.0;
  };
  const auto cut = [&](float alpha) { return alpha >= 1.0f ? core : v.alphaCut(alpha); };
  if (!inside(support.hi)) {  // outside S(θ) for every θ of P(0)
    *out = {0.0f, kNeverInside};
    return true;
  }
  if (!inside(core.hi)) {
    // u = μ̂(ρ) on the falling side, rounded down to a float whose cut still reaches ρ; the
    // witness is that cut's upper end.
    float u = floatDown(hullMembership(v, rho));
    Interval c = cut(u);
    for (int k = 0; k < 8 && u > 0.0f && c.hi < rho; ++k) c = cut(u = std::nextafter(u, -1.0f));
    if (!(u > 0.0f) || c.hi < rho || !inside(c.hi)) return false;
    *out = {u, kNeverInside};
    return true;
  }
  // u = 1 (the witness: the core's upper end).
  if (inside(support.lo)) {  // inside S(θ) for every θ of P(0)
    *out = {1.0f, 0.0f};
    return true;
  }
  if (!inside(core.lo)) {  // a θ of P(1) puts p outside
    *out = {1.0f, kNeverInside};
    return true;
  }
  // l = μ̂(ρ) on the rising side, rounded up to a float whose cut starts at or above ρ: every θ
  // of P(l) puts p inside (its lower end, the F-raising corner, does).
  float l = floatUp(hullMembership(v, rho));
  Interval c = cut(l);
  for (int k = 0; k < 8 && l < 1.0f && c.lo < rho; ++k) c = cut(l = std::nextafter(l, 2.0f));
  if (c.lo < rho || !inside(c.lo)) return false;
  *out = {1.0f, l};
  return true;
}

}  // namespace fsdb
