#pragma once
// How the query tests compare parses: a linguistic query's meaning (its JSON without the words
// each condition covers, so two texts that mean the same query compare equal) and a CSG query's
// graph as a string, op(children...) with leaves by their text, children in graph order.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "query/json/fuzzy_json.h"
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

// A leaf with a relation shows it: 'a sphere'<top 'a cylinder'>, 'a sphere'<right 'a cube' ~2> (the
// distance's core midpoint).
inline std::string csgShape(const CsgQuery& q, int node) {
  const CsgGraphNode& n = q.graph.nodes[node];
  if (n.op == CsgGraphOp::Leaf) {
    const CsgQueryLeaf& leaf = q.leaves[n.leaf];
    std::string out = "'" + leaf.text + "'";
    if (leaf.relation) {
      out += "<" + leaf.relation->direction.word + " '" + q.leaves[leaf.relation->to].text + "'";
      if (leaf.relation->distance) {
        const Interval core = leaf.relation->distance->core();
        char buf[32];
        std::snprintf(buf, sizeof buf, " ~%g", (core.lo + core.hi) / 2);
        out += buf;
      }
      out += ">";
    }
    return out;
  }
  std::string out = std::string(csgGraphOpName(n.op)) + "(";
  for (size_t i = 0; i < n.children.size(); ++i) out += (i ? ", " : "") + csgShape(q, n.children[i]);
  return out + ")";
}
inline std::string csgShape(const CsgQuery& q) { return csgShape(q, q.graph.root); }

// What a CSG query means, whatever its words: leaves by their conditions' meaning (or the part's
// name), relations by direction, distance and the other leaf's meaning, the operands of unions and
// intersections sorted (unordered), a difference's minuend first and its subtrahends sorted.
inline std::string csgMeaning(const CsgQuery& q, int node) {
  const CsgGraphNode& n = q.graph.nodes[node];
  const auto leafMeaning = [&](size_t leaf) {
    const CsgQueryLeaf& l = q.leaves[leaf];
    return l.condition ? queryMeaning(*l.condition).dump() : "part:" + l.text;
  };
  if (n.op == CsgGraphOp::Leaf) {
    const CsgQueryLeaf& leaf = q.leaves[n.leaf];
    std::string out = leafMeaning(size_t(n.leaf));
    if (leaf.relation) {
      out += "<" + leaf.relation->direction.word + " " + leafMeaning(leaf.relation->to);
      if (leaf.relation->distance) out += " " + toJson(*leaf.relation->distance).dump();
      out += ">";
    }
    return out;
  }
  std::vector<std::string> children;
  for (int c : n.children) children.push_back(csgMeaning(q, c));
  std::sort(children.begin() + (n.op == CsgGraphOp::Difference ? 1 : 0), children.end());
  std::string out = std::string(csgGraphOpName(n.op)) + "(";
  for (size_t i = 0; i < children.size(); ++i) out += (i ? ", " : "") + children[i];
  return out + ")";
}
inline std::string csgMeaning(const CsgQuery& q) { return csgMeaning(q, q.graph.root); }

}  // namespace fsdb::testing
