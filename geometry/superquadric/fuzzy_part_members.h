#pragma once
// brief: The family's members (Zhang, Pham & Chen, Figure 1: the "typical shapes" of a fuzzy
// shape, each with its membership degree): crisp parts drawn from a fuzzy part's parameter box
// P(0), and the membership of a crisp part in the fuzzy one, min_i μ_i(θ_i) over its fourteen
// values (§3.2, the degree to which a parameter vector belongs to the fuzzy parameters).
// note: memberAt(part, α, k, first) puts every fuzzy value at one end of its α-cut: value i
// (numbered from `first`, so the parts of one shape draw together) at the high end when
// i + k is odd, so that consecutive members lean opposite ways and every value moves. Crisp
// values and the rotation axis stay. The member's membership is then at least α, and exactly α
// where the membership is continuous at the cut's end (every fuzzy number of docs/api.md §2 with
// sloping sides). At α = 1 the member is the core's ends; coreRepresentative() (the cores'
// midpoints) is the member of membership 1 that the family is ordered from.
// throws: fsdb::Error(errc::kInvalidParameter, "alpha") for α outside [0, 1].
#include <cstddef>

#include "geometry/superquadric/fuzzy_part.h"

namespace fsdb {

// The crisp member at level `alpha`, pattern `k`, values numbered from `first` (a FuzzyPart whose
// values are all crisp).
FuzzyPart memberAt(const FuzzyPart& part, double alpha, size_t k, size_t first = 0);

// The membership of a crisp part `member` (every value crisp) in `part`: the least membership of
// its values in the part's, 1 when every value lies in its core.
double memberMembership(const FuzzyPart& part, const FuzzyPart& member);

// How many values a part has (the slots memberAt numbers): 14.
inline constexpr size_t kPartValues = 14;

}  // namespace fsdb
