// See server/service/family_members.h.
#include "server/service/family_members.h"

#include <algorithm>
#include <unordered_map>

#include "geometry/core/error.h"
#include "geometry/field/csg_field.h"
#include "geometry/superquadric/fuzzy_part_members.h"
#include "query/document/part_json.h"

namespace fsdb {
namespace {

// The leaves of the tree in pre-order, each shared leaf once, with the number of its first value.
void collectLeaves(const CsgTree& node, std::unordered_map<const CsgTree*, size_t>* first,
                   std::vector<const CsgTree*>* order) {
  if (node.leaf) {
    if (first->emplace(&node, order->size() * kPartValues).second) order->push_back(&node);
    return;
  }
  for (const auto& child : node.children) collectLeaves(*child, first, order);
}

// The member's tree: the shape's Booleans with every leaf replaced by its crisp member.
nlohmann::json memberTree(const CsgTree& node, const std::unordered_map<const CsgTree*, FuzzyPart>& members,
                          size_t* nodes, size_t maxNodes) {
  if (++*nodes > maxNodes)
    throw Error(errc::kLimitExceeded,
                "a member of this shape would have more than " + std::to_string(maxNodes) +
                    " nodes (its shared subtrees written at each place); max_nodes bounds it",
                "count");
  if (node.leaf) return {{"part", partToJson(members.at(&node))}};
  nlohmann::json children = nlohmann::json::array();
  for (const auto& child : node.children) children.push_back(memberTree(*child, members, nodes, maxNodes));
  return {{"op", csgOpName(node.op)}, {"children", std::move(children)}};
}

}  // namespace

nlohmann::json familyMembers(const ParsedShape& shape, bool part, int count, size_t maxNodes) {
  if (count < 1 || count > 64) throw Error(errc::kInvalidParameter, "count lies in [1, 64]", "count");
  std::unordered_map<const CsgTree*, size_t> first;
  std::vector<const CsgTree*> leaves;
  collectLeaves(*shape.tree, &first, &leaves);
  struct Member {
    double membership;
    double level;
    nlohmann::json document;
  };
  std::vector<Member> out;
  for (int k = 0; k < count; ++k) {
    const double level = 1.0 - static_cast<double>(k) / count;
    std::unordered_map<const CsgTree*, FuzzyPart> members;
    double membership = 1.0;
    for (const CsgTree* leaf : leaves) {
      const FuzzyPart m = k == 0 ? FuzzyPart::fromCrisp(leaf->part.coreRepresentative())
                                 : memberAt(leaf->part, level, static_cast<size_t>(k), first.at(leaf));
      membership = std::min(membership, memberMembership(leaf->part, m));
      members.emplace(leaf, m);
    }
    nlohmann::json document;
    if (part) {
      document = partToJson(members.at(leaves.front()));
      document["kind"] = "part";
    } else {
      size_t nodes = 0;
      document = {{"kind", "shape"}, {"tree", memberTree(*shape.tree, members, &nodes, maxNodes)}};
    }
    out.push_back({membership, level, std::move(document)});
  }
  std::stable_sort(out.begin(), out.end(), [](const Member& a, const Member& b) { return a.membership > b.membership; });
  nlohmann::json members = nlohmann::json::array();
  for (Member& m : out)
    members.push_back({{"membership", m.membership}, {"level", m.level}, {"document", std::move(m.document)}});
  return {{"count", count}, {"members", std::move(members)}};
}

}  // namespace fsdb
