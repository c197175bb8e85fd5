#pragma once
// Affine-arithmetic enclosure of a placed superquadric's inside-outside function:
// the same quantity as insideOutsideBounds (superquadric_bounds.h), F(p; θ) over a box of points
// and a box of the fourteen part values, computed with affine forms (affine_form.h) along the
// crisp chain (unplace, unbend, untwist, untaper, docs/api.md §2; Zhang, Pham & Chen, eq. 1)
// instead of intervals.
//
// Why: over a box of many fuzzy values the interval chain treats every occurrence of a value as
// independent (C = a1·a3 enters the twist angle, the taper factors and the ratio; the placement
// enters all three coordinates), and a first-order mean value form about the centre carries slope
// intervals that are themselves first-order wide. The affine forms keep one noise symbol per value
// (slot i of superquadric_slopes.h is symbol i; the point box's x, y, z are symbols 14, 15, 16), so
// the linear part of F over the box is exact and only a second-order remainder is added: the
// enclosure's width shrinks quadratically with the box, where the interval one shrinks linearly.
//
// Contract:
//  * Preconditions as insideOutsideBounds (every θ of the box valid, finite point box).
//  * Soundness: the result holds F of every (point, θ) of the boxes (affine_form.h's rounding
//    slack makes that hold under rounding too), intersected with [0, ∞).
//  * Where a form leaves its domain (the bend's 1 − kv·x may reach 0 or kv's interval holds 0, a
//    taper factor may vanish, a value overflows) the answer is the trivial [0, largest double];
//    where a canonical ratio may be near 0 its power is bounded by intervals (that term loses its
//    correlation, the others keep theirs). Callers intersect the result with the interval
//    enclosure: each is sound, and each is the tighter one somewhere.
//  * Exact (up to rounding) for a degenerate box (one θ, one point): both ends equal F.
#include "geometry/numeric/affine_form.h"
#include "geometry/numeric/interval.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb {

Interval insideOutsideAffineBounds(const PartBox& part, const Interval& x, const Interval& y,
                                   const Interval& z);

// The affine form behind it: F(p; θ) = F0 + Σ_i f_i·ε_i ± e with θ_i = mid_i + half_i·ε_i for slot i
// (mid and half width of the box's interval, affineVariable) and the point box's coordinates as
// symbols 14..16. False where the forms leave their domain (then the bound above is trivial).
bool insideOutsideAffineForm(const PartBox& part, const Interval& x, const Interval& y,
                             const Interval& z, AffineForm* f);

// Affine contraction (the linear relaxation of Ninin, Messine and Hansen, "A reliable affine
// relaxation method for global optimization", 4OR 13, 2015): every θ of the box with F(p; θ) <= 1
// (inside) or F(p; θ) > 1 (!inside) satisfies the linear inequality F0 + Σ f_i·ε_i − e <= 1 (or
// F0 + Σ f_i·ε_i + e > 1), so it lies in the box narrowed, value by value, to where that inequality
// can still hold with the other ε at their most favourable ends. Narrows `box` (the box f was
// computed over) to that box, padded by a few ulps, and returns false when no θ can qualify.
// Only the fourteen values are narrowed (the point box is left as it is).
bool contractToQualifying(const AffineForm& f, bool inside, PartBox* box);

}  // namespace fsdb
