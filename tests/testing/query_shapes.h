#pragma once
// How the query tests compare parses: a linguistic query's meaning (its JSON without the words
// each condition covers, so two texts that mean the same query compare equal) and a CSG query's
// graph as a string, op(children...) with leaves by their text, children in graph order.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "query/linguistic/linguistic_query.h"
#include "query/structural/csg_query_text.h"

namespace fsdb::testing {

inline nlohmann::json queryMeaning(const LinguisticQuery& query) {
  nlohmann::json j = toJson(query);
  std::function<void(nlohmann::json&)> strip = [&](nlohmann::json& c) {
    c.erase("text");
    if (c.contains("children"))
      for (nlohmann::json& child : c["children"]) strip(child);
  };
  strip(j["condition"]);
  return j;
}

inline std::string csgShape(const CsgQuery& q, int node) {
  const CsgGraphNode& n = q.graph.nodes[node];
  if (n.op == CsgGraphOp::Leaf) return "'" + q.leaves[n.leaf].text + "'";
  std::string out = std::string(csgGraphOpName(n.op)) + "(";
  for (size_t i = 0; i < n.children.size(); ++i) out += (i ? ", " : "") + csgShape(q, n.children[i]);
  return out + ")";
}
inline std::string csgShape(const CsgQuery& q) { return csgShape(q, q.graph.root); }

}  // namespace fsdb::testing
