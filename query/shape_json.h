#pragma once
// CSG shape documents (SPEC §2, seed 004 §2.3) parsed into the alpha field of the whole tree:
//   {"kind":"shape","name":"lamp",
//    "tree":{"op":"union","operator":{"name":"zadeh"},
//            "children":[{"part":{inline part},"transform":{...}},
//                        {"op":"difference","children":[{"part":{...}},{"part":{...}}]}]}}
// A part document ({"kind":"part",...}) is accepted too, as a one-leaf tree.
//
// Semantics: each leaf is a fuzzy superquadric part (geometry/fuzzy_part_field.h); each inner
// node a Boolean with the exact alpha-cut semantics of SPEC §3 (geometry/csg_field.h), or, with
// a non-zadeh "operator" (fuzzy_operator or blend of GET /operators), a fuzzy-set combination of
// possibility and necessity with crisp parts smoothed to μ(F(P)) (geometry/smooth_csg_field.h);
// such a node takes "range" (world units, > 0) and "step" (a step function, default polynomial
// n = 3), e.g. {"op":"union","operator":{"name":"bezier","n":3},"range":0.1,"children":[...]}. A leaf's
// "transform" places the inline part; a part that has its own transform cannot take a second
// one (fuzzy placements do not compose into one placement in general), which is an error.
//
// Not yet evaluated, and refused with a message naming the path: references to stored parts
// and shapes ("part":"<name>", "ref") and the text form "csg" (both need the store). Limits: more
// than maxNodes nodes is limit_exceeded.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "geometry/alpha_field.h"
#include "geometry/boundary_method.h"

namespace fsdb {

struct ParsedShape {
  std::shared_ptr<const AlphaFieldSource> field;  // the envelope (exact alpha-cut semantics)
  std::shared_ptr<const CsgTree> tree;            // the same tree of fuzzy parts (method boundary)
  size_t nodeCount = 0;  // leaves and Boolean nodes
  size_t partCount = 0;  // leaves
  // JSON path of the first non-zadeh node operator ("shape.tree.operator"); empty if none. The
  // boundary method (tree) knows only the zadeh Booleans.
  std::string smoothOperatorPath;
};

ParsedShape parseShapeField(const nlohmann::json& doc, const std::string& path, size_t maxNodes);

}  // namespace fsdb
