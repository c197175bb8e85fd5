#pragma once
// Similarity of fuzzy numbers (Zhang, Pham & Chen, §5; docs/api.md §5): how well a fuzzy datum
// satisfies a fuzzy condition, the score behind linguistic and CSG queries.
//
//   S(A, B) = min(|A ∩ B| / |A|, |A ∩ B| / |B|),  ∩ = min,  |.| = area under the membership.
//
// S is in [0, 1], symmetric, S(A, A) = 1 and S = 0 when the supports do not overlap (or touch
// only at a point). A crisp value has zero area; the paper's rule then applies: "the
// similarity measure degenerates to the membership degree to which the crisp value belongs to
// the condition fuzzy set", S(x, B) = mu_B(x); two crisp values are 1 if equal, else 0. Both
// rules are the height of A ∩ B (sup of min(mu_A, mu_B)), which is what is used whenever
// either side has zero area (this also covers memberships made only of vertical spikes).
#include "geometry/fuzzy/fuzzy_number.h"

namespace fsdb {

// Exact area under min(mu_A, mu_B) (breakpoints of both plus the points where they cross).
double cardinalityOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b);

// Exact height of A ∩ B, sup of min(mu_A, mu_B) (0 when no value belongs to both: their
// supports are apart or touch only where one of them is 0).
double heightOfIntersection(const FuzzyNumber& a, const FuzzyNumber& b);

double similarity(const FuzzyNumber& a, const FuzzyNumber& b);

// How much of B the datum A spans: |A ∩ B| / |B|, the second ratio of S. A crisp A has no area and
// covers nothing (0); against a crisp B (area 0) it is the height of A ∩ B, as S is. In [0, 1],
// 1 when A = B, and >= S wherever A has area (S is the smaller ratio). The linguistic search
// breaks ties of S with it: of two objects that satisfy the words equally, the one described as
// vaguely as the words comes first (docs/design/linguistic-search.md, "Ties").
double coverage(const FuzzyNumber& a, const FuzzyNumber& b);

// The expected membership of the datum A in B: ∫ mu_A·mu_B / ∫ mu_A, the mean of mu_B over A
// weighted by A's own membership (Zadeh's probability of a fuzzy event, with A normalised to a
// density). A crisp A (no area) gives the height of A ∩ B, mu_B(x) for x, as S does. In [0, 1];
// 1 when A lies in B's core however narrow A is (S is then |A|/|B|), and at most the largest
// mu_B over A's support. The linguistic search scores a noun's defaults with it: "a knob" is
// small, and a knob whose size is fuzzy within "small" is wholly a knob
// (docs/design/linguistic-search.md, "Nouns are defaults").
double expectedMembership(const FuzzyNumber& a, const FuzzyNumber& b);

}  // namespace fsdb
