#pragma once
// The paper's literal alpha-cut construction (Zhang, Pham & Chen, §3.2, eq. 4, Figure 6;
// docs/api.md §3 method "boundary"): at each level α every fuzzy part is replaced by two crisp
// boundary shapes, the corner of its parameter box P(α) with the smallest volume (lower) and the
// one with the largest (upper); Booleans then act on these crisp shapes per level: union and
// intersection pair lower with lower and upper with upper, and difference A − B pairs lower_A with
// upper_B and upper_A with lower_B (docs/api.md §3).
//
// Choices where the paper is silent, documented here:
// - Only the values that change the volume take part in the corner search: eps1, eps2, a1, a2,
//   a3, kx, ky and scale (closed-form volume, geometry/superquadric/superquadric_volume.h). Bend, twist,
//   translation and angle do not change the volume; they sit at the midpoint of their cut.
// - Ties keep the first corner in enumeration order (low ends first).
// Unlike the envelope (geometry/field/alpha_field.h), this is not the union/intersection over the
// whole box: it agrees with it where the shape grows with its volume (a fuzzy size), and differs
// for fuzzy positions and orientations (a fuzzy translation has no swept upper shape here).
#include <memory>
#include <vector>

#include "geometry/field/alpha_field.h"
#include "geometry/field/csg_field.h"
#include "geometry/superquadric/fuzzy_part.h"
#include "geometry/superquadric/placed_superquadric.h"

namespace fsdb {

// A CSG tree of fuzzy parts: a leaf holds a part, an inner node an operation on >= 2 children.
struct CsgTree {
  bool leaf = true;
  FuzzyPart part;
  CsgOp op = CsgOp::kUnion;
  std::vector<std::shared_ptr<const CsgTree>> children;
};

// The crisp corner shape of P(α) with the smallest (largest = false) or largest volume.
PlacedSuperquadric boundaryShape(const FuzzyPart& part, double alpha, bool largest);

// The crisp solid of the whole tree at level α: the lower boundary (upper = false) or the upper.
// Its alpha field is crisp: (u, l) = (1, 0) inside, (0, never) outside.
std::shared_ptr<const AlphaFieldSource> boundarySolid(const CsgTree& tree, double alpha, bool upper);

}  // namespace fsdb
