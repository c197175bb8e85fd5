#pragma once
// Fuzzy sets over a descriptor's degree d ∈ [0, 1] (query/linguistic/descriptors.h): the two
// transformations the words of the vocabulary need. Both are exact on the breakpoints.
#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

// The set restricted to the degrees [0, 1]: pieces that cross 0 or 1 are cut there and the ends
// become vertical sides (a number phrase such as "about 1" as a degree). The core must meet
// [0, 1]; the caller checks it.
FuzzyNumber restrictedToDegrees(const FuzzyNumber& set);

// The set of a low-pole adjective ("flat", "small", "straight"): d → 1 − d.
FuzzyNumber mirroredDegrees(const FuzzyNumber& set);

}  // namespace fsdb
