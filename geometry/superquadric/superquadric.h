#pragma once
// A crisp superquadric part: its nine parameters (Zhang, Pham & Chen, eq. 1) and the inside-outside
// function of its canonical, undeformed solid (docs/api.md §2, "Parameter semantics").
//
// Contract:
//  * Parameters: eps1, eps2 in (0, 4]; a1, a2, a3 > 0; |kx|, |ky| <= 1; |kv|·C < π; t any real.
//    validate() throws fsdb::Error(kInvalidParameter) whose path names the parameter.
//  * Half-lengths: A = a1, B = a1·a2, C = a1·a3.
//  * Inside-outside F(p) = ((|x|/A)^(2/eps2) + (|y|/B)^(2/eps2))^(eps2/eps1) + (|z|/C)^(2/eps1);
//    p is inside iff F(p) <= 1 (F < 1 interior, F = 1 surface).
//  * The evaluation functions below take canonical (undeformed, unplaced) points and assume
//    validated parameters; deformation.h and placed_superquadric.h map other points here.
//  * For finite points none of them returns NaN. F and the pseudo distance never return
//    infinity: they saturate at the largest finite double (F only ever answers "how far
//    outside", and F <= 1 is exact either way). G is finite unless its true value is beyond
//    the doubles (coordinates near 1e308 over half-lengths below 1).
#include "geometry/core/vec3.h"

namespace fsdb {

struct SuperquadricParams {
  double eps1 = 1.0;  // squareness north-south (along z)
  double eps2 = 1.0;  // squareness east-west (in the xy cross-section)
  double a1 = 1.0;    // overall size: the x half-length
  double a2 = 1.0;    // y half-length / x half-length
  double a3 = 1.0;    // z half-length / x half-length
  double kx = 0.0;    // taper along x
  double ky = 0.0;    // taper along y
  double kv = 0.0;    // bending curvature (1 / length), bending plane xz
  double t = 0.0;     // twist: radians of rotation about z from z = 0 to z = C

  // Half-lengths of the canonical solid along x, y, z.
  double A() const { return a1; }
  double B() const { return a1 * a2; }
  double C() const { return a1 * a3; }

  // Throws fsdb::Error(errc::kInvalidParameter, message, "<parameter>") for the first
  // parameter outside its range (NaN and infinities included); the message states the range.
  void validate() const;
};

// G = F^(eps1/2): the same solid (G <= 1 iff F <= 1) but homogeneous of degree one,
// G(λp) = λ·G(p) for λ >= 0, so it grows like a length instead of like |p|^(2/eps1).
// G(0) = 0.
double homogeneousInsideOutside(const SuperquadricParams& params, const Vec3& p);

// F as in the contract above, saturated at the largest finite double.
double insideOutside(const SuperquadricParams& params, const Vec3& p);

// Radial pseudo signed distance d = |p|·(1 − 1/G(p)) = |p| − ρ(p/|p|), where ρ(u) = 1/G(u)
// is the distance from the centre to the surface along the unit direction u. Negative inside,
// zero on the surface, positive outside; for a sphere of radius r it is exactly |p| − r. It
// is not the Euclidean distance of other shapes, but it is continuous away from the centre
// and has the right sign and zero set, which is what level sets need. At p = 0 there is no
// direction: we return −min(A, B, C), the value along the shortest principal axis.
double pseudoDistance(const SuperquadricParams& params, const Vec3& p);

}  // namespace fsdb
