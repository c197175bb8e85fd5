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

// The set of a low-pole adjective ("flat", "small", "straight"): d → 1 − d.
FuzzyNumber mirroredDegrees(const FuzzyNumber& set);

}  // namespace fsdb
