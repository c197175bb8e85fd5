#pragma once
// FuzzyPart: a fuzzy superquadric part (docs/api.md §2 "Part"; Zhang, Pham & Chen, §2.1): every
// shape parameter and every placement value is a fuzzy number; the rotation axis is crisp.
//
// Contract:
//  * Defaults are crisp and give the unit sphere at the origin with the identity placement.
//  * validate() checks that the whole support box is valid, so every parameter vector the
//    alpha-cuts can produce is a valid crisp part (superquadric.h, transform.h): each support lies
//    in its documented range (docs/api.md §2: eps in (0, 4], a1, a2, a3 > 0, |kx|, |ky| <= 1,
//    scale > 0, all finite) and |kv|·C < π for the largest |kv| and C = a1·a3 of the box. Errors:
//    fsdb::Error(errc::kInvalidParameter) with the document path of the bad value ("params.eps1",
//    "params.kv", "transform.translate[0]", "transform.rotate.axis", "transform.rotate.deg",
//    "transform.scale").
//  * boxAt(alpha) is the parameter box P(α) of docs/api.md §3: each value's alpha-cut (its hull for
//    non-convex memberships), alpha = 0 giving the support's closure. alpha outside [0, 1] throws
//    errc::kInvalidParameter with path "alpha".
//  * coreRepresentative() is the crisp part at the midpoints of the cores (a member of P(1)).
//  * breakpointLevels() is the sorted union of every membership breakpoint height, with 0 and 1:
//    between two consecutive levels every alpha-cut end of every value is linear in α.
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"
#include "geometry/superquadric/placed_superquadric.h"
#include "geometry/superquadric/superquadric_bounds.h"
#include "geometry/core/vec3.h"

namespace fsdb {

struct FuzzyPart {
  // Shape (docs/api.md §2 parameter semantics).
  FuzzyNumber eps1 = FuzzyNumber::crisp(1.0), eps2 = FuzzyNumber::crisp(1.0);
  FuzzyNumber a1 = FuzzyNumber::crisp(1.0), a2 = FuzzyNumber::crisp(1.0),
              a3 = FuzzyNumber::crisp(1.0);
  FuzzyNumber kx = FuzzyNumber::crisp(0.0), ky = FuzzyNumber::crisp(0.0),
              kv = FuzzyNumber::crisp(0.0), t = FuzzyNumber::crisp(0.0);
  // Placement: translate, rotate (crisp axis, fuzzy degrees), scale.
  FuzzyNumber tx = FuzzyNumber::crisp(0.0), ty = FuzzyNumber::crisp(0.0),
              tz = FuzzyNumber::crisp(0.0);
  Vec3 axis{0.0, 0.0, 1.0};
  FuzzyNumber deg = FuzzyNumber::crisp(0.0);
  FuzzyNumber scale = FuzzyNumber::crisp(1.0);

  // A crisp part as a fuzzy one.
  static FuzzyPart fromCrisp(const PlacedSuperquadric& part);

  void validate() const;
  PartBox boxAt(double alpha) const;
  PlacedSuperquadric coreRepresentative() const;
  std::vector<double> breakpointLevels() const;
};

}  // namespace fsdb
