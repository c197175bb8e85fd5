#pragma once
// CSG shape documents (docs/api.md §2; Zhang, Pham & Chen, §2.3) parsed into the alpha field of
// the whole tree:
//   {"kind":"shape","name":"lamp",
//    "tree":{"op":"union","operator":{"name":"zadeh"},
//            "children":[{"part":{inline part},"transform":{...}},
//                        {"op":"difference","children":[{"part":{...}},{"part":{...}}]}]}}
// A part document ({"kind":"part",...}) is accepted too, as a one-leaf tree.
//
// Semantics: each leaf is a fuzzy superquadric part (geometry/field/fuzzy_part_field.h); each inner
// node a Boolean with the exact alpha-cut semantics of docs/api.md §3 (geometry/field/csg_field.h), or, with
// a non-zadeh "operator" (fuzzy_operator or blend of GET /operators), a fuzzy-set combination of
// possibility and necessity with crisp parts smoothed to μ(F(P)) (geometry/field/smooth_csg_field.h);
// such a node takes "range" (world units, > 0) and "step" (a step function, default polynomial
// n = 3), e.g. {"op":"union","operator":{"name":"bezier","n":3},"range":0.1,"children":[...]}. A leaf's
// "transform" places the inline part; a part that has its own transform cannot take a second
// one (fuzzy placements do not compose into one placement in general), which is an error.
//
// References to stored objects (docs/api.md §2) go through a ReferenceResolver (the server backs it
// with the store; query/ knows no database):
//   {"part":"bolt"} or {"part":7}   a stored part by name or id (with an optional leaf transform)
//   {"ref":"wheel"} or {"ref":12}   a stored shape by name or id: its tree is evaluated in place
//   {"kind":"shape","csg":"C = A + (B - D) * E"}   the text form (query/document/csg_text.h); each name is
//                                   a stored part, else a stored shape
// A stored object referenced several times (shared subtrees, a DAG) is parsed and built once
// and counts once against maxNodes. Unknown references are unknown_reference (422) with the
// path of the reference; a shape that reaches itself is reference_cycle (422). Without a
// resolver, references are invalid_document naming the path.
// A leaf's transform may be a placement from words against an earlier leaf (query/document/placement_words.h:
// {"place":{"relative_to":"base","direction":"above","distance":"about 3"}}).
// Not yet evaluated: a transform on a "ref" leaf (a fuzzy placement of a whole subtree does not
// reduce to the placements of its parts).
// Limits: more than maxNodes nodes is limit_exceeded.
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/field/alpha_field.h"
#include "geometry/field/boundary_method.h"

namespace fsdb {

struct ParsedShape {
  std::shared_ptr<const AlphaFieldSource> field;  // the envelope (exact alpha-cut semantics)
  std::shared_ptr<const CsgTree> tree;            // the same tree of fuzzy parts (method boundary)
  size_t nodeCount = 0;  // leaves and Boolean nodes
  size_t partCount = 0;  // leaves
  // JSON path of the first non-zadeh node operator ("shape.tree.operator"); empty if none. The
  // boundary method (tree) knows only the zadeh Booleans.
  std::string smoothOperatorPath;
  // The document's tree with its "csg" text parsed (names resolved to "part"/"ref" leaves): what
  // shapeTree returns, kept so callers (outlineTree) need not parse and resolve the text again.
  // Null for a part document.
  nlohmann::json documentTree;
  std::string documentTreePath;  // its JSON path: path + ".tree" or path + ".csg"
};

// A stored document that a reference names.
struct ResolvedReference {
  int64_t id = 0;           // the stored object's id: identity for sharing and cycle checks
  nlohmann::json document;  // its latest version
};
// kind: "part" or "shape"; key: the reference as written (a name string or an integer id).
// Returns nullopt for an unknown reference.
using ReferenceResolver =
    std::function<std::optional<ResolvedReference>(const std::string& kind, const nlohmann::json& key)>;

// `resolver` with each answer remembered (for one parse, or one caller's several passes over the same
// document): the csg text asks for every name (as a part, then as a shape) and the walk asks again for
// the same reference when it builds the leaf. An empty resolver stays empty.
ReferenceResolver rememberingResolver(const ReferenceResolver& resolver);

ParsedShape parseShapeField(const nlohmann::json& doc, const std::string& path, size_t maxNodes,
                            const ReferenceResolver& resolver = {});

// The tree of a shape document: its "tree", or its "csg" text parsed (names resolved to "part"
// or "ref" leaves with `resolver`). invalid_document when it has neither or both.
nlohmann::json shapeTree(const nlohmann::json& doc, const std::string& path, const ReferenceResolver& resolver);

// A reference as written in a document, found without resolving anything.
struct DocumentReference {
  std::string kind;      // "part" or "shape"
  nlohmann::json key;    // name string or integer id
  std::string path;      // "tree.children[1].part"
};

// One node of a tree in pre-order (root first, parent -1), for storage and structural search.
struct TreeNodeOutline {
  int parent = -1;
  int position = 0;
  std::string kind;              // "union", "intersection", "difference", "part", "ref"
  nlohmann::json operatorDoc;    // the node's "operator" (null when absent)
  nlohmann::json transform;      // the leaf's "transform" (null when absent)
  int reference = -1;            // index into the references, for leaves naming a stored object
};

struct TreeOutline {
  std::vector<TreeNodeOutline> nodes;
  std::vector<DocumentReference> references;
};

// Walks a tree (as shapeTree returns it) without parsing parts or resolving references.
// The tree must have passed parseShapeField (malformed trees are not diagnosed here).
TreeOutline outlineTree(const nlohmann::json& tree, const std::string& path);

}  // namespace fsdb
