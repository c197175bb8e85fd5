#pragma once
// The world box of a family of placed superquadrics: a box that holds S(θ) for every θ of a
// parameter box (a fuzzy part's upper(0) when the box is P(0)), found through the forward maps
// rather than the inside-outside function.
//
// Why: a solid's extent is the extent of its points, and every point of the deformed, placed
// part is the image of a canonical point under taper, twist, bend and placement
// (deformation.h, transform.h). Enclosing those maps over small cells of the canonical solid
// bounds the extent to about a cell's image, where a bound built on F over world cells
// (superquadric_bounds.h) stays loose for bent, twisted and turned parts (a thin bent rod's box
// was 2× its extent).
//
// How: the canonical box [−A, A] × [−B, B] × [−C, C] (largest half-lengths) is split depth first
// across its widest side. A cell is dropped when no θ of the box has a canonical point in it (the
// homogeneous G, increasing in |x|/A, |y|/B, |z|/C and the exponents, exceeds 1 at its nearest
// corner with the smallest exponents and largest half-lengths), or when its image (interval taper,
// twist, bend, scale, turn and translation over the cell and the parameter box) lies in the hull
// found so far. Cells of the finest size add their image to the hull. The hull starts from points
// of the mid part's surface, so cells well inside the extent go early.
//
// Contract:
//  * Precondition: every θ of the box is valid (as superquadric_bounds.h).
//  * Sound: every point of S(θ) for every θ of the box lies in [lo, hi], up to rounding (no
//    outward rounding; the box is padded by 1e-9 of its size for that). A point whose bend is
//    folded (deformation.h, "Domain of the bend inverse") is still the image of a canonical
//    point, so it is held too.
//  * Tight to about a finest cell's image: `cells` finest cells across each canonical side.
//  * Bounded: at most `budget` cells are tested; when that runs out, the images of the cells
//    still open join the hull (sound, looser).
#include "geometry/core/vec3.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb {

struct PartExtentOptions {
  int cells = 64;        // finest cells across each canonical side
  int budget = 200000;   // cells tested at most
};

void partExtent(const PartBox& part, Vec3* lo, Vec3* hi, PartExtentOptions options = {});

}  // namespace fsdb
