#pragma once
// Closest matches of a query that no object meets (docs/design/linguistic-search.md, "No dead
// ends"): the query relaxed so that objects near its conditions score above 0, ranked by how
// near they are, while explain still says what the words asked.
#include "query/linguistic/linguistic_query.h"

namespace fsdb {

// The query with every descriptor condition outside a "not" widened by `widenBy` degrees and
// every relation's placement ignored.
// - Widening adds the triangular number tri(−w, 0, w) to the condition's set by the extension
//   principle (Zhang, Pham & Chen, §3.2, eq. 3): each α-cut grows by w·(1 − α) on each side, so
//   the core is kept and the support reaches w further; a value w outside the support of a set
//   with vertical sides scores about 1 − distance / w. w = 0 widens nothing.
// - A condition under "not" is left as asked: widening it would make the negation stricter.
// - A relation scores its two noun phrases over the best ordered pair of components, wherever
//   they stand ("a cone resting on a box": a shape with a cone and a box).
// - Each changed descriptor condition keeps the set it asked in `asked`, and the query is marked
//   `closestMatch`, so every explain entry gives both scores (ConditionScore::score as asked,
//   ::closeness relaxed); the subject, aggregation, threshold and words are unchanged.
// Throws fsdb::Error(errc::kInvalidParameter, path "widen_by") for w < 0 or not finite.
LinguisticQuery closestMatchQuery(const LinguisticQuery& query, double widenBy);

}  // namespace fsdb
