#pragma once
// The structure of a CSG shape as a rooted graph, for structural search (Zhang, Pham & Chen, §5;
// docs/api.md §5): the query tree and each stored tree become a CsgGraph, compared by
// query/structural/common_subgraph.h and scored by query/structural/csg_similarity.h.
//
// Contract:
//  * A node is an operation (union, intersection, difference) or a leaf. Children of union and
//    intersection are unordered; a difference's children[0] is the minuend and children[1..] the
//    subtrahends (unordered among themselves, as A − B − C = A − (B ∪ C)).
//  * The graph is a rooted DAG: a stored shape referenced several times ({"ref"}, docs/api.md §2
//    shared subtrees) is ONE node with several parents. A parent naming the same shared node twice
//    keeps both edges (children lists may repeat an index).
//  * Nested unions (and nested intersections) with the same operator document are flattened into one
//    n-ary node (associativity: "A + B + C" and "(A + B) + C" give the same graph). A shared node is
//    never flattened into its parents (that would copy it and lose the sharing); nor is a node whose
//    "operator" differs from its parent's (a bezier union inside a zadeh union is another operation).
//  * Leaf payloads live beside the graph in the caller's own vector, indexed by node.leaf.
//  * path is the JSON path of the node in its document, the way errors name it ("tree.children[1]";
//    inside a referenced shape "tree.children[0].ref.tree.children[1]"); a shared node keeps the path
//    of its first occurrence in pre-order.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/superquadric/fuzzy_part.h"
#include "query/document/shape_json.h"

namespace fsdb {

enum class CsgGraphOp { Union, Intersection, Difference, Leaf };
const char* csgGraphOpName(CsgGraphOp op);  // "union","intersection","difference","leaf"

struct CsgGraphNode {
  CsgGraphOp op = CsgGraphOp::Leaf;
  std::vector<int> children;  // node indices; order matters only for Difference: children[0] is the
                              // minuend, children[1..] the subtrahends (unordered among themselves)
  int leaf = -1;              // Leaf: index into the caller's leaf payload vector (0..leafCount-1)
  std::string path;           // JSON path of the node in its document ("tree.children[1]"), for mappings
};

// Structure only: a rooted DAG (a tree when no node has two parents). Leaf payloads (parts, or the
// conditions of a text query) live beside it in the caller's own vector, indexed by node.leaf.
struct CsgGraph {
  std::vector<CsgGraphNode> nodes;
  int root = 0;
  int leafCount = 0;
  bool isTree() const;  // no node reachable by two parent edges
  // The path of each leaf's node, by CsgGraphNode::leaf (a shared leaf: its first node's).
  std::vector<std::string> leafPaths() const;
  size_t size() const { return nodes.size(); }
  // Parent indices of each node (one entry per edge, so a doubly named child lists its parent twice).
  std::vector<std::vector<int>> parents() const;
};

// A stored or inline shape/part document as a graph + its leaves' fuzzy parts (leaf transform applied
// to the part as geometry/superquadric/fuzzy_part.h does for evaluation). Referenced shapes ({"ref"}) shared by
// several parents become ONE node with several parents (a DAG), identified by ResolvedReference::id.
// Nested unions (and nested intersections) with the same operator are flattened into one n-ary node
// (associativity; so "A + B + C" and "(A + B) + C" have the same graph). Errors as parseShapeField
// (the document is parsed by it: unknown references, cycles, limit_exceeded beyond maxNodes, bad parts).
// A part document is a one-leaf graph whose leaf path is `path`.
struct CsgGraphLeaf {
  FuzzyPart part;       // geometry/superquadric/fuzzy_part.h
  int64_t partId = 0;   // stored part id when the leaf is a reference, 0 when inline
  std::string name;     // the part's name ("" when an inline part has none)
};
struct ShapeGraph {
  CsgGraph graph;
  std::vector<CsgGraphLeaf> leaves;
};
ShapeGraph shapeGraph(const nlohmann::json& doc, const std::string& path, size_t maxNodes,
                      const ReferenceResolver& resolver = {});

}  // namespace fsdb
