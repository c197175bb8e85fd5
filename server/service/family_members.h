#pragma once
// brief: The family's members of a stored part or shape (GET /parts/{id}/members and GET
// /shapes/{id}/members?count=N; docs/api.md §4; Zhang, Pham & Chen, Figure 1): N crisp documents
// drawn from the fuzzy parameters of every part of it, each with its membership degree, ordered
// from the core (1) outward.
// note: Member 0 takes every value at its core's midpoint; member k of N lies at level
// α = 1 − k/N, every fuzzy value of every part at one end of its α-cut (memberAt,
// geometry/superquadric/fuzzy_part_members.h, the parts numbered in one sequence so they lean
// together). Its membership is the least over all values of all parts (at least α). A shape's
// member is its Boolean tree with crisp inline parts; node operators other than the Booleans
// (smooth operators, blends) are not in it, and a subtree the shape shares is written at each of
// its places.
// throws: fsdb::Error(invalid_parameter, "count") for a count outside [1, 64];
// fsdb::Error(limit_exceeded, "count") when a member's document would exceed maxNodes nodes.
#include <nlohmann/json.hpp>

#include "query/document/shape_json.h"

namespace fsdb {

nlohmann::json familyMembers(const ParsedShape& shape, bool part, int count, size_t maxNodes);

}  // namespace fsdb
