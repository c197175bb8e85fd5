#pragma once
// Interval slopes of a placed superquadric's inside-outside function: enclosures of
// the partial derivatives ∂F/∂θ_i of F(p; θ) (PlacedSuperquadric::insideOutside) with respect to
// the fourteen part values θ, over a box of points and a box of parameters. Forward-mode automatic
// differentiation in interval arithmetic (the interval gradient of global optimisation's
// monotonicity test, Hansen & Walster, "Global Optimization Using Interval Analysis", §12.4).
//
// Use (fuzzy_part_field.h): where every ∂F/∂θ_i keeps one sign over the boxes, F is monotone in
// each value there, so its minimum and maximum over any sub-box of parameters are two known
// corners, exactly.
//
// Contract:
//  * Values are addressed by slot (partSlot): 0 eps1, 1 eps2, 2 a1, 3 a2, 4 a3, 5 kx, 6 ky, 7 kv,
//    8 t, 9 tx, 10 ty, 11 tz, 12 deg (degrees), 13 scale.
//  * insideOutsideSlopes(part, x, y, z, slots, count, out) differentiates with respect to the
//    `count` slots listed in `slots` (the others are held at their intervals) and, when it returns
//    true, out[j] holds ∂F/∂θ_{slots[j]} for every point of x × y × z and every θ of `part`
//    (preconditions as insideOutsideBounds: every θ of the box valid; finite point box). Where F
//    has a kink (|x| at x = 0) the enclosure holds the one-sided derivatives, which is what the
//    mean value theorem for Lipschitz functions needs. No outward rounding: ends may be off by a
//    few ulps of the intermediate values, as for insideOutsideBounds.
//  * It returns false where it cannot bound the slopes: a taper factor, the bend's 1 − kv·x or a
//    fuzzy kv may vanish over the boxes, a canonical ratio may be 0 under an exponent below 1,
//    or an intermediate value is not finite. Callers then treat every slope as unknown.
#include "geometry/numeric/interval.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb {

inline constexpr int kPartSlots = 14;

// The interval of slot i (order above) of a part box (inline: the searches call it in their
// inner loops).
inline Interval& partSlot(PartBox& b, int i) {
  switch (i) {
    case 0: return b.params.eps1;
    case 1: return b.params.eps2;
    case 2: return b.params.a1;
    case 3: return b.params.a2;
    case 4: return b.params.a3;
    case 5: return b.params.kx;
    case 6: return b.params.ky;
    case 7: return b.params.kv;
    case 8: return b.params.t;
    case 9: return b.placement.tx;
    case 10: return b.placement.ty;
    case 11: return b.placement.tz;
    case 12: return b.placement.deg;
    default: return b.placement.scale;
  }
}
inline const Interval& partSlot(const PartBox& b, int i) {
  return partSlot(const_cast<PartBox&>(b), i);
}

// The crisp part whose values are v, in slot order, with the given rotation axis.
PlacedSuperquadric partFromSlots(const Vec3& axis, const double (&v)[kPartSlots]);

bool insideOutsideSlopes(const PartBox& part, const Interval& x, const Interval& y,
                         const Interval& z, const int* slots, int count, Interval* out);

// The mean value form of F(p; θ) over the box about Baumann's optimal centre (E. Baumann, "Optimal
// centered forms", BIT 28, 1988): its lower end when `lower`, else its upper end, for d[j] ⊇
// {∂F/∂θ_{slots[j]}} over the box at p (as insideOutsideSlopes gives them). Every value of the box
// not listed must be a single value; otherwise, and where F at the centre or the sum is not finite,
// the answer is the trivial −∞ (lower) or +∞. One crisp evaluation of F. Rounding as above (no
// outward rounding: a few ulps).
double meanValueEnd(const PartBox& part, const Vec3& p, bool lower, const int* slots, int count,
                    const Interval* d);

}  // namespace fsdb
