#pragma once
// Internal to geometry/field/fuzzy_part_*.cpp: the helpers that the field, its max-min search
// (fuzzy_part_search.cpp), its monotone shortcut (fuzzy_part_monotone.cpp) and its block proof
// (fuzzy_part_block.cpp) share. Not a public header: nothing outside those files includes it.
#include <algorithm>

#include "geometry/field/fuzzy_part_field.h"
#include "geometry/numeric/affine_form.h"
#include "geometry/numeric/interval_functions.h"
#include "geometry/superquadric/superquadric_affine.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb::part_field_detail {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSlots = kPartSlots;  // superquadric_slopes.h's slot order
// The enclosure is not rounded outwards (superquadric_bounds.h: a few ulps); block decisions that
// levelsAt must reproduce keep this relative distance from the threshold 1.
constexpr double kMargin = 1e-12;
// A box narrower than this, relative to the support, in every value is treated as one θ.
constexpr double kDegenerate = 1e-12;
// Slack added to membership bounds: the interpolation in membership() rounds (a few ulps).
constexpr double kMembershipSlack = 1e-12;

// Whether an enclosure f of F over a box shows that no θ of the box serves the search: inside
// looks for F <= 1 (excluded when f.lo > 1), outside for F > 1 (excluded when f.hi <= 1).
inline bool excludes(const Interval& f, bool inside) { return inside ? f.lo > 1.0 : f.hi <= 1.0; }

// The fourteen fuzzy values of a part box, addressed by index for splitting.
inline Interval& slot(PartBox& b, int i) { return partSlot(b, i); }
inline const Interval& slot(const PartBox& b, int i) { return partSlot(b, i); }

// F at the centre of the box: a crisp witness (every θ of a validated part's box is valid).
inline double centreValue(const PartBox& b, const Vec3& p) { return midpointPart(b).insideOutside(p); }

// The enclosure of F over the box at p that the point searches use: the interval enclosure
// (superquadric_bounds.h) and, unless it already excludes the box for the search it serves
// (inside: lo > 1, no θ with F <= 1; else hi <= 1, none with F > 1), intersected with the affine
// one (superquadric_affine.h). Both are sound; the affine one keeps the correlations between the
// fourteen values along the inverse deformations, so over the small boxes of a search it is
// usually the tighter (its remainder is second order), at about the cost of the interval one.
// The same over a box of points x × y × z (the block proof's enclosure); *evaluations, when given,
// counts each of the two enclosures taken.
inline Interval boxEnclosure(const PartBox& b, const Interval& x, const Interval& y, const Interval& z,
                             bool inside, int* evaluations = nullptr) {
  if (evaluations) ++*evaluations;
  const Interval f = insideOutsideBounds(b, x, y, z);
  if (excludes(f, inside)) return f;
  if (evaluations) ++*evaluations;
  return intersect(f, insideOutsideAffineBounds(b, x, y, z));
}

inline Interval pointEnclosure(const PartBox& b, const Vec3& p, bool inside) {
  return boxEnclosure(b, {p.x, p.x}, {p.y, p.y}, {p.z, p.z}, inside);
}

// The search's enclosure step (maxMin): the enclosure of pointEnclosure over the box at p, and the
// box narrowed by affine contraction (contractToQualifying, superquadric_affine.h) to the θ that
// can still qualify (inside: F <= 1, else F > 1): every such θ stays in it, so the search loses
// nothing it looks for. False when no θ of the box qualifies. *f encloses F over the box before
// the narrowing (so over the narrowed box too); *narrowed tells whether the box changed; on true, *form is
// the affine form of F over the box before the narrowing (form->valid false where there is none).
// (Taking the enclosure of the narrowed box again changed no answer and no exhaustion count of the
// bench part at N = 32, so one round.)
inline bool narrowToQualifying(PartBox* box, const Vec3& p, bool inside, Interval* f, bool* narrowed,
                               AffineForm* form) {
  const Interval px{p.x, p.x}, py{p.y, p.y}, pz{p.z, p.z};
  *narrowed = false;
  *f = insideOutsideBounds(*box, px, py, pz);
  if (excludes(*f, inside)) return false;
  if (!insideOutsideAffineForm(*box, px, py, pz, form)) {
    form->valid = false;
    return true;
  }
  const Interval a = range(*form);
  *f = intersect(*f, {std::max(a.lo, 0.0), std::max(a.hi, 0.0)});
  if (excludes(*f, inside)) return false;
  const PartBox before = *box;
  if (!contractToQualifying(*form, inside, box)) return false;
  for (int i = 0; i < kSlots && !*narrowed; ++i) {
    const Interval& w = partSlot(before, i);
    const Interval& n = partSlot(*box, i);
    *narrowed = w.lo != n.lo || w.hi != n.hi;
  }
  return true;
}

// The monotone collapse: each of the `count` values `open` whose slope d[j] keeps one sign is set
// to its end where F is least (towardsLeast) or largest; true when any value was. Where F is
// monotone in those values over the box, F's least (largest) value over the box is taken on the
// collapsed box.
inline bool collapseMonotone(PartBox* box, const int* open, int count, const Interval* d,
                             bool towardsLeast) {
  bool collapsed = false;
  for (int j = 0; j < count; ++j) {
    const int sign = d[j].lo >= 0.0 ? 1 : d[j].hi <= 0.0 ? -1 : 0;
    if (sign == 0) continue;
    Interval& v = slot(*box, open[j]);
    const double end = (sign > 0) == towardsLeast ? v.lo : v.hi;
    v = {end, end};
    collapsed = true;
  }
  return collapsed;
}

// Quasi-concave envelope of a membership (the membership whose cuts are the hulls boxAt uses):
// μ̂(x) = min(max_{y <= x} μ(y), max_{y >= x} μ(y)), so θ_i ∈ cut_i(α) ⇔ μ̂_i(θ_i) >= α (α > 0).
inline double hullMembership(const FuzzyNumber& v, double x) {
  const double mu = v.membership(x);
  double left = mu, right = mu;
  for (const Breakpoint& b : v.breakpoints()) {
    if (b.x <= x) left = std::max(left, b.mu);
    if (b.x >= x) right = std::max(right, b.mu);
  }
  return std::min(left, right);
}

// sup of μ̂ over [a, b]: 1 where the interval meets the core, else the end nearer to the core
// (μ̂ rises up to the core and falls after it).
inline double supHullMembership(const FuzzyNumber& v, const Interval& core, const Interval& x) {
  if (x.hi >= core.lo && x.lo <= core.hi) return 1.0;
  return hullMembership(v, x.hi < core.lo ? x.hi : x.lo);
}

inline PlacedSuperquadric thetaAt(const PartBox& b, const double (&v)[kSlots]) {
  return partFromSlots(b.placement.axis, v);
}

}  // namespace fsdb::part_field_detail
