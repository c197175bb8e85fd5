#pragma once
// Closed-form volumes of superquadric parts (used for fuzzy volumes, docs/api.md §3).
//
//  * Canonical solid (Jaklič, Leonardis & Solina 2000, "Segmentation and Recovery of
//    Superquadrics", ch. 2, volume of a superellipsoid):
//      V = 2·A·B·C·eps1·eps2·β(eps1/2 + 1, eps1)·β(eps2/2, eps2/2).
//    Sphere: 4/3·π·r³; box limit (eps -> 0): 8·A·B·C; cylinder limit (eps1 -> 0, eps2 = 1):
//    2·π·A·B·C.
//  * Taper multiplies it by 1 + kx·ky·β(3·eps1/2, eps1 + 1) / (2·β(eps1/2 + 1, eps1)).
//    Derivation: the taper's Jacobian is (1 + kx·z/C)(1 + ky·z/C) >= 0 on the part; the
//    linear terms integrate to 0 by symmetry in z, and ∫z² dV / V = C²·β(3eps1/2, eps1 + 1) /
//    (2·β(eps1/2 + 1, eps1)) by the same Beta-function integral as V.
//  * Twist rotates each z-slice rigidly: Jacobian 1. Bend has Jacobian 1 − kv·x (polar
//    coordinates about the bending axis); the tapered, twisted part is symmetric under
//    (x, y) -> (−x, −y), so ∫x dV = 0 and the total volume is unchanged. This holds when the
//    bend is one-to-one on the part (bendIsInjectiveOnPart, deformation.h); otherwise the
//    bent solid is smaller than the value given here.
//  * Placement scales volume by scale³.
// All functions assume validated parameters.
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric.h"

namespace fsdb {

// Euler's Beta function β(a, b) = Γ(a)Γ(b)/Γ(a + b) for a, b > 0, through log-Gamma so that
// tiny arguments (β(0.01, 0.01) ~ 200 while Γ(0.01)² ~ 1e4 and Γ(1e-200) overflows) stay finite.
double betaFunction(double a, double b);

double canonicalVolume(const SuperquadricParams& params);     // undeformed solid
double taperVolumeFactor(const SuperquadricParams& params);   // volume ratio tapered / undeformed
double superquadricVolume(const SuperquadricParams& params);  // canonical · taper factor
double placedVolume(const PlacedSuperquadric& part);          // scale³ · superquadricVolume

}  // namespace fsdb
