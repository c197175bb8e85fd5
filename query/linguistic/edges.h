#pragma once
// A part's edges, as words say them ("a cube with rounded edges", "a cylinder with sharp
// edges", "a rounded box").
//
// A superquadric's edges are its exponents below 1: a box's eps1 and eps2 (its edges and its
// corners), a cylinder's eps1 alone (the rims of its ends: its eps2 = 1 makes the round section,
// which has no edge). Rounding the edges raises those exponents towards 1 and keeps the others;
// sharpening them lowers them towards 0. A noun with no exponent below 1 (a ball, a double
// pyramid) or no shape ("shape") has both taken as its edges.
//
// The words give a degree d of the vocabulary's edge descriptor (Vocabulary::edgeDescriptor,
// roundness in the built-in vocabulary) for each edge exponent: the edge set, the sharp edge set
// or an intensity's. The part's own descriptor is then the mean over eps1 and eps2 (descriptors.h):
//   D = (k·d + Σ_other f(ε_o)) / 2,
// with k the number of edge exponents and f the descriptor's function of one exponent
// (exponentDegree), d read over the descriptor's degree domain (descriptors.h) where k = 1. That
// image is what a query asks of the part (edgeDescriptorSet), and a part
// made from the words sets its edge exponents to the inverse of d (part_from_words.h), so the
// words find it.
#include "geometry/fuzzy/fuzzy_number.h"
#include "query/linguistic/vocabulary.h"

namespace fsdb {

// Which of eps1, eps2 are a noun's edges (see above); `noun` may be null (no noun: both).
struct EdgeExponents {
  bool eps1 = true;
  bool eps2 = true;
};
EdgeExponents edgeExponentsOf(const Noun* noun);

// The set of `vocabulary`'s edge descriptor a part of `noun` has when its edge exponents have
// degree `d` and its other exponents keep the noun's: the affine image above (exact).
FuzzyNumber edgeDescriptorSet(const FuzzyNumber& d, const Noun* noun, const Vocabulary& vocabulary);

}  // namespace fsdb
