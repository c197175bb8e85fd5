// The JSON of a parsed linguistic query (toJson in query/linguistic/linguistic_query.h): the
// "parsed" member of POST /query/linguistic answers.
#include <nlohmann/json.hpp>

#include "query/json/fuzzy_json.h"
#include "query/linguistic/linguistic_query.h"

namespace fsdb {
namespace {

using Kind = QueryCondition::Kind;

const char* kindName(Kind k) {
  switch (k) {
    case Kind::kDescriptor: return "descriptor";
    case Kind::kAnd: return "and";
    case Kind::kOr: return "or";
    case Kind::kNot: return "not";
    case Kind::kRelation: return "relation";
  }
  return "";
}

nlohmann::json conditionJson(const QueryCondition& c) {
  nlohmann::json j = {{"kind", kindName(c.kind)}, {"text", c.text}};
  if (c.kind == Kind::kDescriptor) {
    j["descriptor"] = c.descriptor;
    j["set"] = toJson(c.set);
    if (c.measure) j["measure"] = toJson(*c.measure);  // the extent in world units
    if (c.relativeTo < 1.0) j["relative_to"] = c.relativeTo;  // scores min(1, s / relative_to)
  }
  if (c.kind == Kind::kRelation) {
    j["direction"] = c.direction;
    j["distance"] = c.distance ? toJson(*c.distance) : nlohmann::json();
  }
  if (c.kind != Kind::kDescriptor) {
    j["children"] = nlohmann::json::array();
    for (const QueryCondition& child : c.children) j["children"].push_back(conditionJson(child));
  }
  return j;
}

}  // namespace

nlohmann::json toJson(const LinguisticQuery& query) {
  return {{"subject", query.subject},
          {"aggregation", query.aggregation},
          {"at_least", query.atLeast},
          {"condition", conditionJson(query.root)}};
}

}  // namespace fsdb
