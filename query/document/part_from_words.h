#pragma once
// Parts described by words (docs/api.md §2: {"kind":"part","text":"a slightly bent cylinder"}): the
// noun gives the base parameters (vocabulary "nouns.*.params"), each adjective sets the
// parameters its descriptor reads to the fuzzy degree its words mean, through the inverse of
// the descriptor function (the "create" rules of schema/vocabulary.json):
//   squariness  eps1 = eps2 = max(0.05, 1 − d) roundness  eps1 = eps2 = max(0.05, d)
//   bevelness   eps1 = eps2 = 1 + d            pinchness  eps1 = eps2 = 2 + 2·d
//   section-squariness  eps2 = max(0.05, 1 − d) section-roundness  eps2 = max(0.05, d)
//   elongation  a2 = 1, a3 = 2d (d < 1/2) or 1 / (2 − 2d), d clamped to [0.02, 0.98]
//   slenderness the longer of B, C = the middle half-length / (1 − d), d clamped to [0, 0.96]
//   flatness    the shorter of B, C = (1 − d) · the middle half-length, d clamped to [0, 0.96]
//   bendness    kv = d·π / (2C)                taperness  kx = ky = −d (narrowing towards +z)
//   twistness   t = π·d
//   size        transform.scale = (d / (1 − d)) / L, d clamped to [0.05, 0.95]
//   length, width, thickness, height: the extent e = d / (1 − d) (d clamped to [0.02, 0.98]), or a
//               measure's extent in world units ("a pole about 10 long": length about 10), set on
//               the axis it measures (realizeExtents: the noun's axes sorted by length say which
//               is which; an axis as long as a measured one follows it; height is C). The
//               extents are the tapered solid's (descriptors.h): "a cone 2 across" has a base
//               2 across, its A the base's half over the taper's widening.
// with C and L (query/linguistic/descriptors.h) of the part so far (core midpoints). The degree d is the
// intensity's set ("slightly bent": `slightly`), else the adjective's own "create", else the
// vocabulary's plain "create" set; low-pole adjectives ("narrow", "small") mirror the intensity and
// plain sets (d → 1 − d; an adjective's own "create" is its degree as written). Adjectives act in
// the order shape, proportions, size, taper, extents, bend and twist, whatever their order in the
// text, so a bend is measured on the final length and an extent on the final taper; measures override an adjective of the same extent. Affine rules are exact; elongation and
// size map the set's breakpoints (exact there, linear between).
// Edges ("a box with rounded edges", "a rounded box", "a cylinder with sharp edges") act after
// the shape's adjectives: the noun's edge exponents (query/linguistic/edges.h: those below 1; a
// cylinder's eps1 alone) take the edge degree through the rule of the vocabulary's edge
// descriptor above (roundness: ε = max(0.05, d)); the others keep what the words gave them.
// An exponent word beside a noun whose own exponent shape the words keep (a box's squareness:
// "a round box", the paper's rounded box) moves the exponents along the word's path (eps1 = eps2
// = e, or eps2 alone for a section word) to where the same words, read as a query, score the
// part highest: the word's own shape could score 0 for the noun, and the words did not find it.
// A word the grammar lacks is routed onto the vocabulary first (query/linguistic/word_routes.h:
// its lemma, WordNet's links), so "a skinny pole" is made as "a thin pole"; the document keeps
// the words as written.
// Errors: fsdb::Error(errc::kInvalidParameter, path "text"): the parser's (unknown words with the
// closest known ones, position, expected words), a noun without a shape ("shape", "part": say
// which primitive), and parameters outside the ranges of docs/api.md §2.
#include <string>

#include "geometry/superquadric/fuzzy_part.h"

namespace fsdb {
class Vocabulary;

FuzzyPart partFromWords(const std::string& text, const Vocabulary& vocabulary);

}  // namespace fsdb
