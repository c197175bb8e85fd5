#pragma once
// Structural queries (Zhang, Pham & Chen, §5; docs/api.md §4 POST /query/csg): the query tree of a
// text or of a shape document, as the graph that query/structural/common_subgraph.h compares with
// stored trees, and the payloads of its leaves.
//
// Text, two forms (grammar and examples: schema/csg_query_grammar.ebnf; a test parses every example):
//  * phrases: "the union of a very bent cylinder and a very sharp pyramid", "a cube minus a
//    cylinder", "the intersection of a sphere and a box", "a sphere and a box" (a list is a union),
//    nested ("the union of a cube and the difference of a box and a cylinder") or parenthesised:
//      csg_query = [ request ] , [ lead_in ] , expr      (* request and fillers: the linguistic ones *)
//      lead_in   = [ article ] GENERIC ( "which" | "that" ) ( "is" | "are" ) [ made_of ] (* before a construction *)
//                | [ [ article ] GENERIC ] made_of        (* GENERIC: "shape", "something", ...; made_of: "made of", ... *)
//      expr      = list , { ( "minus" | "without" | "drilled" [ "through" ] [ "with" | "by" ] ) , list
//                           | "with" hole | "with" meet cut_out }   (* difference, left to right *)
//      hole      = [ article ] [ shape word ] "hole"   ("cylindrical", "sphere-shaped", ...; none: a cylinder)
//      list      = meet , { ( "," [ "and" ] | "and" | "plus" | "united with" | "combined with" | "joined with"
//                           | "joined to" | "together with" | "along with" | "with" ) , meet }   (* union *)
//      meet      = item , { "intersected" , "with" , item }             (* intersection *)
//      item      = "(" , expr , ")"
//                | [ article ] , "part" , "of" , item , ( "inside" | "within" | "in" ) , item   (* intersection *)
//                | [ article ] , ( "union" | "intersection" ) , "of" , item , { ( "," [ "and" ] | "and" ) , item }
//                | [ article ] , "difference" , "of" , item , "and" , item
//                | noun_phrase , [ relation ]                            (* query/linguistic/linguistic_query.h *)
//      relation  = [ distance ] , ( ( "to" | "on" | "at" ) , "the" , DIRECTION , [ "side" ] , "of" , object
//                                 | DIRECTION , "of" , object | PHRASE , object     (PHRASE: "above", "on top of", ...)
//                                 | ( "to" | "on" | "at" ) , ( "its" | "the" ) , DIRECTION , [ "side" ]
//                                 | "on" , "top" | PHRASE )      (* no object: the operand before this one *)
//      distance  = number_phrase , [ "unit" | "units" ] | DISTANCE_WORD    ("about 2 units", "close")
//      object    = "it" (* the operand before *) | item (* its head leaf: "a cube" of "a cube on top of a box" *)
//    "Y on top of X" is the union of Y and X with Y placed against X; "X and Y to its right" places Y
//    against X, the operand before it in the same list (an operation has no single part to point at:
//    an error then names the relation's words).
//    A noun phrase ends after its noun and relative clause (parseNounPhraseAt), so "and" joins
//    operands unless a condition follows it ("a bent and twisted rod" is one leaf). "union of"
//    lists take every following item; "difference of" takes exactly two (use "minus" for more).
//  * formula: the CSG text of query/document/csg_text.h, "C = A + (B - D) * E". Each name is a stored part
//    (a part leaf), else a stored shape (its whole tree in place, through `resolver`), else a
//    description: a noun phrase, quoted when it has blanks ("\"very bent cylinder\" + cube").
//    A text is the formula form when isCsgFormula says so.
// Leaves: a description is a linguistic condition (scored against a stored leaf's descriptor values
// with scoreDescriptors; it says nothing about placement, so the search gives it transform
// similarity 1 against any stored leaf); a part leaf is compared with partSimilarity and
// transformSimilarity (query/structural/csg_similarity.h).
// The graph is built by shapeGraph (query/structural/csg_graph.h) from a shape document whose description
// leaves are placeholder parts, so a query and a stored tree of the same structure give the same
// graph (flattened unions and intersections, shared stored shapes).
// Errors: fsdb::Error(invalid_parameter, path "text") with the character position (0-based, as the
// linguistic parser gives it) and the expected words, e.g. "unexpected 'of' at character 4; expected
// ...". More than maxNodes nodes is limit_exceeded (413).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/superquadric/fuzzy_part.h"
#include "query/structural/csg_graph.h"
#include "query/linguistic/linguistic_query.h"
#include "query/document/shape_json.h"

namespace fsdb {

// A spatial relation of a description leaf (Zhang, Pham & Chen, §2.2): "a sphere on top of a
// cylinder", "a cube and a sphere about 2 units to its right". The leaf's centre lies in
// `direction` from the centre of leaf `to`, at `distance` (none: any distance); scored by
// query/structural/csg_relations.h.
struct CsgRelation {
  size_t to = 0;                         // the leaf it is placed against (index into CsgQuery::leaves)
  Direction direction;                   // the direction's sets, from the parser's vocabulary
  std::optional<FuzzyNumber> distance;   // between the two centres
  std::string text;                      // the words: "about 2 units to its right"
};

struct CsgQueryLeaf {
  std::string text;                           // a description's words, or the part's name
  std::optional<LinguisticQuery> condition;   // set: a description
  FuzzyPart part;                             // otherwise: the part (its leaf transform applied)
  int64_t partId = 0;                         // a stored part's id, 0 for inline parts and descriptions
  std::optional<CsgRelation> relation;        // phrase form only: where this leaf lies against another
};

struct CsgQuery {
  std::string form;                  // "phrase", "formula" or "tree"
  CsgGraph graph;                    // node paths point into `tree` ("tree.children[1]")
  std::vector<CsgQueryLeaf> leaves;  // by CsgGraphNode::leaf
  nlohmann::json tree;               // the query tree: {"op","children"} nodes; description leaves
                                     // {"text","condition"} (condition: the linguistic parse), part
                                     // leaves as written ({"part":...}, {"ref":...})
};

// A text of either form. `resolver` looks names of the formula form up (none: every name is a description).
CsgQuery parseCsgQuery(const std::string& text, const Vocabulary& vocabulary, const ReferenceResolver& resolver,
                       size_t maxNodes);

// The member "tree" of a request: a shape document (or a part document) or a bare shape tree
// ({"op":...} or a leaf); every leaf a part (form "tree"). Errors as shapeGraph, with the paths of
// the request body ("tree.children[1].part.params.a1"; "tree.tree.children[1]..." inside a document).
CsgQuery csgQueryFromDocument(const nlohmann::json& tree, size_t maxNodes, const ReferenceResolver& resolver);

// Whether a text is the formula form: it holds one of + * = " or a "-" that is not inside a word
// (a word is letters, digits, "-", "'", "."; so "A - B" and "A -B" are formulas, "cube-like" is not).
// A sign inside a number ("about 2.5e+32 units", "-3") is no operator.
bool isCsgFormula(const std::string& text);

// Whether `fsdb query` should send a text to the CSG search rather than the linguistic one: a
// formula, a text with one of the words union, intersection, difference, minus, without, plus,
// intersected, or a text that is no linguistic query but a phrase-form CSG query ("a sphere and a box").
bool isCsgQueryText(const std::string& text, const Vocabulary& vocabulary);

// {"form","tree","nodes","leaves"} for the "parsed" member of POST /query/csg.
nlohmann::json toJson(const CsgQuery& query);

// The words the phrase form reads besides the linguistic ones (operation words, joiners, holes,
// relations, units, lead-ins), sorted: with knowsLinguisticWord, what a search-box text may say.
const std::vector<std::string>& csgPhraseWords();

}  // namespace fsdb
