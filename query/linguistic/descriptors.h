#pragma once
// Shape descriptors (Zhang, Pham & Chen, §5: "squariness, roundness, bevelness, pinchness,
// bendness, taperness, and twistness, to index shape components"; fsdb adds size, elongation and
// the traverse section's squariness and roundness):
// each a documented function of a crisp part's parameters giving a degree in [0, 1].
// schema/vocabulary.json publishes the same definitions for users; this header is the reference.
//
// With A = a1, B = a1·a2, C = a1·a3 (docs/api.md §2) and, per exponent e in (0, 4],
//   sq(e) = max(0, 1 − e)          1 at e → 0 (box-like), 0 from e = 1
//   ro(e) = max(0, 1 − |e − 1|)    1 at e = 1 (ellipsoidal), 0 at 0 and 2
//   be(e) = max(0, 1 − |e − 2|)    1 at e = 2 (straight edges, sharp vertices: a double pyramid)
//   pi(e) = clamp((e − 2) / 2)     0 up to e = 2, 1 at e = 4 (concave, pinched faces)
// the descriptors are
//   squariness = (sq(eps1) + sq(eps2)) / 2       roundness = (ro(eps1) + ro(eps2)) / 2
//   bevelness  = (be(eps1) + be(eps2)) / 2       pinchness = (pi(eps1) + pi(eps2)) / 2
//   bendness   = min(1, |kv|·2C / π)   the total bend angle (curvature × arc length ≈ 2C)
//                                      relative to a half turn
//   taperness  = max(|kx|, |ky|)       the taper (|k| <= 1: 1 tapers to a point)
//   twistness  = min(1, |t| / π)       the total twist 2|t| (t per half-length C) relative to a
//                                      full turn
//   size       = L / (1 + L),  L = scale · (A + B + C) / 3   (the mean half-length in world
//                                      units; a unit sphere is 0.5; a plate 6 across and 0.1
//                                      thick 0.67, a stub 2 across and 1 long 0.45: the face
//                                      people see, where the geometric mean, a volume's, made
//                                      the plate the smaller)
//   elongation = (1 + s1/s2 − s2/s3) / 2 with s1 <= s2 <= s3 the sorted half-lengths A, B, C:
//                1 for a needle (s3 >> s2 = s1), 0 for a sheet (s1 << s2 = s3), 0.5 when the
//                three are equal (and for a part both long and flat).
//   section-squariness = sq(eps2)   section-roundness = ro(eps2)
//                the traverse (cross) section alone: eps2 shapes the section across the z axis
//                (Zhang, Pham & Chen, §2.1: "squareness along the west-east direction"), so a
//                cylinder has a round section and a pyramid a squarish one ("a very sharp shape
//                with squarish traverse section", §1).
//   length, width, thickness = d(e3), d(e2), d(e1) with e1 <= e2 <= e3 the part's full extents
//                along its own axes, 2·scale·(A·fx, B·fy, C), and d(e) = e / (1 + e) as for size:
//                a cylinder 10 long and 1 across has length d(10), width and thickness d(1); a
//                board 8 × 1 × 0.2 has length d(8), width d(1), thickness d(0.2). fx, fy are the
//                taper's widening (taperedHalfWidthFactor(ε1, kx), deformation.h): the tapered
//                solid's widest section over its untapered one, so a cone's width is its base's
//                diameter (a sharp cone with A = 0.5 is 1.91 across, not 1).
//   height     = d(2·scale·C), the extent along the part's own z axis (the axis its taper, bend
//                and twist follow): a post's height is its length, a dome's its thickness.
//                The bend and the twist are not in the four: a bent rod's length is its length
//                along its axis, a twisted bar's width its section's.
//                Measures in queries ("about 10 long", "2 across", "3 units tall") are conditions
//                on them (query/linguistic/linguistic_query.h, measureSet).
//   flatness    = 1 − s1/s2   how much thinner the part is than it is wide: 0.9 for a plate 10
//                             times thinner than its side, 0 for a cube or a rod
//   slenderness = 1 − s2/s3   how much longer the part is than it is wide: 0.9 for a rod 10 times
//                             longer than across, 0 for a cube or a square plate
//                (s1 <= s2 <= s3 the sorted half-lengths, as for elongation.) A board 8 × 1 × 0.2
//                is both (flatness 0.8, slenderness 0.875), where elongation puts it at 0.54,
//                between a plate and a rod: "long" and "flat" are words on these two.
// Every function is continuous and piecewise monotone in each parameter.
//
// Degree domains (degreeDomain): where a descriptor's end is a limit no part reaches (squariness 1
// is ε = 0, size 1 an infinite part, flatness 1 a sheet of no thickness), parts are made to within
// kLeastDegree = 0.01 of it (query/document/part_from_words.h), and every degree is read clamped
// into [0.01, 0.99] at that end: a part with ε = 0.005 reads squariness 0.99, as square as any
// part is made. The search reads the words' sets over the same domain (withinDegreeDomains,
// linguistic_query.h), so the part that "a very square box" makes satisfies those words fully
// (S = 1), as a crisp very square box does, instead of losing the sliver above 0.99 that no part
// can have. Domains: squariness, section-squariness, flatness, slenderness [0, 0.99]; roundness,
// section-roundness [0.01, 1] (a part made round to a degree d has ε = d, at least 0.01); size,
// elongation, length, width, thickness, height [0.01, 0.99]; the others [0, 1].
//
// A fuzzy part's descriptor values are fuzzy numbers by the extension principle (Zhang, Pham &
// Chen, §3.2): the alpha-cut of a value is the image of the parameter box P(α) (FuzzyPart::boxAt).
// The image is computed exactly at each level: every function above is monotone in each parameter
// between its critical values (e = 0, 1, 2; kv, kx, ky, t = 0; a2 = 1, a3 = 1, a2 = a3), so the
// extremes over a box lie on the box's corners with those critical values put in where they fall
// inside. Levels: FuzzyPart::breakpointLevels() plus k/kDescriptorLevels (k/kMeasureLevels for the
// four measures and the two proportions); linear in α between them
// (FuzzyNumber::fromAlphaCuts). A crisp part has crisp values.
#include <string>
#include <vector>

#include "geometry/fuzzy/fuzzy_number.h"
#include "geometry/superquadric/fuzzy_part.h"
#include "geometry/superquadric/superquadric_bounds.h"

namespace fsdb {

// Uniform levels k/16 added to the parts' breakpoint levels.
inline constexpr int kDescriptorLevels = 16;
// The measures (length, width, thickness, height) and the proportions (flatness, slenderness) use
// k/kMeasureLevels with the breakpoint levels.
inline constexpr int kMeasureLevels = 4;

// The descriptor names in index order: "squariness","roundness","bevelness","pinchness",
// "bendness","taperness","twistness","size","elongation","section-squariness","section-roundness",
// "length","width","thickness","height","flatness","slenderness".
const std::vector<std::string>& descriptorNames();

// How many descriptors there were before the two section descriptors (vocabulary files of then
// document only these).
inline constexpr size_t kDescriptorsBeforeSections = 9;
// How many there were before the four measures (length, width, thickness, height).
inline constexpr size_t kDescriptorsBeforeMeasures = 11;
// How many there were before the two proportions (flatness, slenderness).
inline constexpr size_t kDescriptorsBeforeProportions = 15;

// A world-unit extent e as the degree the measure descriptors use: e / (1 + e), 0 for e <= 0.
double extentDegree(double e);
// A fuzzy extent in world units ("about 10": tri(9, 10, 11)) as a set over those degrees: its
// alpha-cuts at its breakpoints and at k/kMeasureLevels mapped through extentDegree, linear in
// between (the same levels a fuzzy part's descriptor values have).
FuzzyNumber extentDegreeSet(const FuzzyNumber& extent);

// What one exponent e gives a whole-shape exponent descriptor (index 0-3: sq, ro, be, pi above):
// squariness and roundness, bevelness and pinchness are the mean of it over eps1 and eps2. Throws
// invalid_parameter for any other index.
double exponentDegree(int index, double e);

// Index of a name in descriptorNames(), or -1.
int descriptorIndex(const std::string& name);

// How far from an end no part reaches its degrees are made and read (see "Degree domains" above).
inline constexpr double kLeastDegree = 0.01;
// The degrees parts have of descriptor `index` (see "Degree domains" above): every degree below is
// clamped into it. [0, 1] for an index out of range.
Interval degreeDomain(int index);

struct DescriptorValue {
  std::string descriptor;  // one of descriptorNames()
  FuzzyNumber value;       // the part's degree (extension principle through the descriptor's function)
};

// The degree of descriptor `index` for a crisp part (the functions above).
double descriptorDegree(int index, const PlacedSuperquadric& part);

// [min, max] of descriptor `index` over a parameter box (exact, see above).
Interval descriptorRange(int index, const PartBox& box);

// Every descriptor of a part, in descriptorNames() order. Deterministic, pure, thread-safe.
std::vector<DescriptorValue> describePart(const FuzzyPart& part);

// brief: How far two described parts lie apart: the sum over the descriptors both have, except
//   those in `skip`, of the distance between their cores' midpoints, in degrees (each in [0, 1]).
// note: The search box breaks ties of score with it (docs/design/linguistic-search.md, "Typical
//   first"): of the objects that meet the words equally, the one nearest the part the words make,
//   their prototype, comes first. A descriptor only one side has (rows written before it existed)
//   is left out.
double descriptorDistance(const std::vector<DescriptorValue>& a, const std::vector<DescriptorValue>& b,
                          const std::vector<std::string>& skip = {});

}  // namespace fsdb
