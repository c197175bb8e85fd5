#pragma once
// The global deformations of a superquadric part (docs/api.md §2), each with its exact inverse.
// Forward order, canonical -> deformed: taper, then twist, then bend. A deformed point is
// evaluated by undoing them in reverse order (unbend, untwist, untaper) and asking the
// canonical inside-outside function (superquadric.h).
//
//  * taper:  X = x·(kx·z/C + 1),  Y = y·(ky·z/C + 1),  Z = z.
//  * twist:  rotation about z by θ = t·z/C:  X = x cos θ − y sin θ,  Y = x sin θ + y cos θ,  Z = z.
//  * bend:   Solina & Bajcsy 1990 ("Recovery of parametric models from range images: the case
//            for superquadrics with global deformations", IEEE PAMI 12(2)) with bending-plane
//            angle α = 0, i.e. in the xz plane, curvature k = kv (1/length), y unchanged:
//              γ = z·k,  R = 1/k − cos γ·(1/k − x),
//              X = x + (R − x) = 1/k − cos γ·(1/k − x),   Y = y,   Z = sin γ·(1/k − x).
//            (Solina's r = cos(α − θ)·√(x² + y²) is x when α = 0.) The z axis becomes an arc of
//            radius 1/k about the bending axis {x = 1/k, z = 0}; arc length along it is z.
//            Positive kv bends the ends of the part towards +x. kv = 0 is the identity.
//
// Domain of the bend inverse. Write s = 1 − k·x (the distance to the bending axis, in units
// of 1/|k|). The bend maps (x, z) to polar coordinates (radius s/|k|, angle γ = k·z) about the
// bending axis, so it is one-to-one on the region {s > 0, |γ| < π}: the half-space on the
// near side of the bending axis, within half a turn. unbend() returns that principal
// preimage for every point: s = |(1 − kX, kZ)| > 0 and γ = atan2(kZ, 1 − kX) in (−π, π].
// The documented range |kv|·C < π (docs/api.md §2) keeps |γ| < π for every point of the part
// (|z| <= C). If the tapered, twisted part reaches across the bending axis (|kv|·|x| >= 1 somewhere
// on it; see bendIsInjectiveOnPart), the forward bend folds that piece over the rest; undoing it
// then recovers only the principal preimage, so the evaluated solid is the bend of the part's
// portion with k·x < 1. A point exactly on the bending axis (s = 0) unbends to (1/k, y, 0).
//
// Taper is singular where kx·z/C + 1 = 0 (or the ky factor), possible only at |z| >= C, i.e.
// outside the part: there untaper returns 0 for a zero coordinate and ±infinity otherwise
// (no canonical point maps there except those with that coordinate 0), which the
// inside-outside functions read as "outside".
#include "geometry/superquadric/superquadric.h"
#include "geometry/core/vec3.h"

namespace fsdb {

Vec3 taper(const SuperquadricParams& params, const Vec3& p);
Vec3 untaper(const SuperquadricParams& params, const Vec3& p);

Vec3 twist(const SuperquadricParams& params, const Vec3& p);
Vec3 untwist(const SuperquadricParams& params, const Vec3& p);

Vec3 bend(const SuperquadricParams& params, const Vec3& p);
Vec3 unbend(const SuperquadricParams& params, const Vec3& p);

// bend(twist(taper(p))): canonical -> deformed.
Vec3 deformPoint(const SuperquadricParams& params, const Vec3& p);
// untaper(untwist(unbend(p))): deformed -> canonical.
Vec3 undeformPoint(const SuperquadricParams& params, const Vec3& p);

// A sufficient condition for the bend to be one-to-one on the whole tapered, twisted part:
// |kv|·√((A·(1 + |kx|))² + (B·(1 + |ky|))²) < 1, a bound on |x| after taper and twist.
// When it holds, the bent solid is exactly the image of the part and bending preserves its
// volume; when it fails, see "Domain of the bend inverse" above.
bool bendIsInjectiveOnPart(const SuperquadricParams& params);

// brief: The tapered solid's largest half-width across one axis, over its half-length there
//   (A or B): max over heights w = |z|/C in [0, 1] of (1 − w^(2/ε1))^(ε1/2) · (1 + |k|·w), the
//   superquadric's section edge at that height (y = 0 for x) times the taper factor on the side
//   the taper widens. A cone (ε1 = 0.1, k = −1) is 1.91 times as wide at its base as its
//   untapered A; a box (ε1 → 0) 1 + |k|; an ellipsoid (ε1 = 1) with k = 1 is 1.30.
// note: 1 where k = 0 or ε1 >= 2: the section edge then falls at least as fast as the taper
//   rises, so the middle is widest. Otherwise the maximum is the one root of
//   w^(2/ε1 − 1)·(1 + 2|k|w) = |k| (the derivative of the logarithm), found by bisection; the
//   product rises with |k| and falls with ε1, so extents built on it keep those directions.
// Preconditions: ε1 in (0, 4], |k| <= 1 (SuperquadricParams::validate's ranges).
double taperedHalfWidthFactor(double eps1, double k);

}  // namespace fsdb
