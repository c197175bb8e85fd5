#pragma once
// Interval extension of a placed superquadric's inside-outside function: for a
// box of world points (a voxel block) and a box of part parameters (a fuzzy part's
// alpha-cuts, docs/api.md §3), an interval that holds F(p; θ) for every point p and every θ in the
// boxes. A block with hi <= 1 is inside the part for every θ (in lower(α)); one with lo > 1 is
// outside for every θ (not in upper(α)); only the rest needs refining.
//
// Contract:
//  * Precondition: every parameter vector in the box is valid (SuperquadricParams::validate,
//    Placement::validate: eps in (0, 4], sizes > 0, |kx|, |ky| <= 1, |kv|·C < π for every C in
//    the box, scale > 0, finite ends); the point box is finite.
//  * Soundness: the result holds PlacedSuperquadric::insideOutside of every (point, θ) in the
//    boxes, up to rounding: no outward rounding is done, so an end may be off by a few ulps
//    of the intermediate values (relative errors around 1e-15). Classification compares with
//    1 and refines boundary blocks, so a few ulps only move blocks that touch the surface.
//  * The result lies in [0, largest finite double] and is never NaN: like the crisp F it
//    saturates instead of overflowing. Boxes beyond any voxel grid (coordinates or
//    translations above 1e150, scale or half-lengths below 1e-150, or canonical coordinates
//    that leave that range) get the trivial, sound answer [0, largest finite double]: this
//    keeps every interval product finite, so no ∞·0 = NaN can hide inside a min or max.
//  * Tightness: for a degenerate box (a crisp part and one point) both ends equal the crisp
//    value up to rounding; for boxes in smooth regions the width shrinks linearly with the
//    box (convergence order 1). The enclosure is looser, but still sound, where the point box
//    straddles the bending axis or the twist covers many turns.
#include "geometry/numeric/interval.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/core/vec3.h"

namespace fsdb {

// The nine superquadric parameters as intervals (each a fuzzy parameter's alpha-cut).
struct SuperquadricBox {
  Interval eps1{1, 1}, eps2{1, 1}, a1{1, 1}, a2{1, 1}, a3{1, 1};
  Interval kx{0, 0}, ky{0, 0}, kv{0, 0}, t{0, 0};
};

// A placement whose translation, angle (degrees) and scale are intervals; the rotation axis
// is crisp (finite, non-zero, any length).
struct PlacementBox {
  Interval tx{0, 0}, ty{0, 0}, tz{0, 0};
  Vec3 axis{0.0, 0.0, 1.0};
  Interval deg{0, 0};
  Interval scale{1, 1};
};

struct PartBox {
  SuperquadricBox params;
  PlacementBox placement;
};

// Turns (x, y) about z by any angle of θ (radians): x' = x·cos θ − y·sin θ, y' = x·sin θ +
// y·cos θ, enclosed for every point of x × y and every angle (the twist, and with −θ its
// inverse).
void turnEnclosure(const Interval& theta, Interval* x, Interval* y);

// The degenerate box of a crisp part: every interval a single value.
PartBox crispPartBox(const PlacedSuperquadric& part);

// The crisp part at the midpoint of every interval of the box (the inverse of crispPartBox on
// degenerate boxes).
PlacedSuperquadric midpointPart(const PartBox& box);

// Does the box hold this crisp part (same axis direction, every value within its interval)?
bool contains(const PartBox& box, const PlacedSuperquadric& part);

// An enclosure of F = PlacedSuperquadric::insideOutside over the point box x × y × z and the
// parameter box `part`; see the contract above.
Interval insideOutsideBounds(const PartBox& part, const Interval& x, const Interval& y,
                             const Interval& z);

// Half-extents (X, Y, Z) of a box [−X, X] × [−Y, Y] × [−Z, Z] of local (unplaced) coordinates
// that holds the deformed part S(θ) in its own frame for every θ of the box: the canonical
// half-lengths at their largest, widened by the taper, turned by the twist within the corner
// circle and swung by the bend (the derivation is in the .cpp).
void deformedHalfExtents(const SuperquadricBox& q, double* X, double* Y, double* Z);

// True when, for every θ of `part`, no point of x × y × z maps into that local box (unplace by
// the placement box, as the enclosure does), or, one map further in, the inverse bend of the
// local box (interval unbend, as the enclosure's) misses the unbent hull: |z| <= C, |x| <= A(1 +
// |kx|), |y| <= B(1 + |ky|), or with a twist the radius of those two (F <= 1 needs every
// canonical ratio <= 1, and then the taper factors lie in [1 − |k|, 1 + |k|]). Then F > 1 there,
// however loose the enclosure of the deformations is (near the bending axis, where the bent
// hull reaches and the inverse bend's z spans most of a turn, the unbent x is about 1/kv). The
// miss keeps a relative margin of 1e-9 (no outward rounding).
bool missesDeformedHull(const PartBox& part, const Interval& x, const Interval& y,
                        const Interval& z);

// The same for the homogeneous G = F^(eps1/2) (superquadric.h): G <= 1 iff F <= 1, and G grows
// like a length, so it suits narrow bands around the surface. Never NaN; the upper end may be
// +infinity (where the crisp G overflows, and for the out-of-range boxes above).
Interval homogeneousInsideOutsideBounds(const PartBox& part, const Interval& x,
                                        const Interval& y, const Interval& z);

}  // namespace fsdb
