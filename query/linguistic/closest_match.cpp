// Closest-match queries (query/linguistic/closest_match.h).
#include "query/linguistic/closest_match.h"

#include <cmath>

#include "geometry/core/error.h"
#include "geometry/fuzzy/fuzzy_arithmetic.h"

namespace fsdb {
namespace {

void relax(QueryCondition* c, double widenBy) {
  using Kind = QueryCondition::Kind;
  switch (c->kind) {
    case Kind::kNot:
      return;  // as asked (see the header)
    case Kind::kDescriptor:
      if (widenBy > 0.0) {
        if (!c->asked) c->asked = c->set;
        c->set = add(*c->asked, FuzzyNumber::triangular(-widenBy, 0.0, widenBy));
      }
      return;
    case Kind::kRelation:  // its placement: LinguisticQuery::closestMatch
    case Kind::kAnd:
    case Kind::kOr:
      break;
  }
  for (QueryCondition& child : c->children) relax(&child, widenBy);
}

}  // namespace

LinguisticQuery closestMatchQuery(const LinguisticQuery& query, double widenBy) {
  if (!std::isfinite(widenBy) || widenBy < 0.0)
    throw Error(errc::kInvalidParameter, "a closest match widens by 0 or more degrees", "widen_by");
  LinguisticQuery relaxed = query;
  relax(&relaxed.root, widenBy);
  relaxed.closestMatch = true;
  return relaxed;
}

}  // namespace fsdb
