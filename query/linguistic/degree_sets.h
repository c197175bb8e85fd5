#pragma once
// Fuzzy sets over a descriptor's degree d ∈ [0, 1] (query/linguistic/descriptors.h): the two
// transformations the words of the vocabulary need. Both are exact on the breakpoints.
#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

// The set restricted to the degrees [lo, hi] (by default all of them, [0, 1]): pieces that cross
// lo or hi are cut there and the ends become vertical sides (a number phrase such as "about 1" as
// a degree; the degrees a part made from words can have). The set must be above 0 somewhere
// inside (lo, hi); the caller checks it.
FuzzyNumber restrictedToDegrees(const FuzzyNumber& set, double lo = 0.0, double hi = 1.0);

// The set read over the degrees [lo, hi] a descriptor has (its domain, descriptors.h:
// degreeDomain): cut at an end of the domain inside the scale (lo > 0, hi < 1) as
// restrictedToDegrees cuts, where the set reaches beyond that end and its core reaches inside the
// domain (so the cut set keeps its core); otherwise kept as it is. What the search scores objects
// against (their degrees are clamped into the domain), and what a part made from words takes
// (query/document/part_from_words.cpp, which makes a set whose core lies wholly beyond an end
// that end, crisp), so that the part satisfies its words fully.
FuzzyNumber withinDegrees(const FuzzyNumber& set, double lo, double hi);

// The set of a low-pole adjective ("flat", "small", "straight"): d → 1 − d.
FuzzyNumber mirroredDegrees(const FuzzyNumber& set);

}  // namespace fsdb
