#pragma once
// Typical first (docs/design/linguistic-search.md, "Typical first"): of the objects that meet a
// text's words with equal scores, the one nearest the part the words make (their prototype: the
// noun's usual geometry with the adjectives' degrees, query/document/part_from_words.h) comes
// first. Concept theory's typicality (Rosch): "a box" is the plain box before the brick that
// also is one, and a part made from "a tapered box" before the pyramid its words also fit.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "db/store.h"
#include "query/linguistic/descriptors.h"

namespace fsdb {

class StoredGraphCache;

// brief: The descriptor values of the part `text` makes (describePart(partFromWords(text))).
// note: nullopt where the words make no part: a relation, an operation, a noun with no shape of
//   its own ("a slightly bent shape"), words the part grammar lacks. Never throws.
std::optional<std::vector<DescriptorValue>> wordsPrototype(const std::string& text);

// brief: Each result's distance to the prototype (descriptorDistance; a shape's least over its
//   components, plus 1 for each other component: a whole of several parts is a less typical
//   instance of words that describe one), in the results' order; +infinity where the store has no current rows for it
//   (pending, or a result without an integer id and a kind). One read of the rows per kind.
// `parsed` (the answer's "parsed": the meaning read) says which descriptors the words name: the
// size and the four measures count only where they do, since a part's size is the noun's
// default, not a word's, where the words say none ("a long flat box" of any size).
std::vector<double> typicalityDistances(const Store& store, const nlohmann::json& results,
                                        const std::vector<DescriptorValue>& prototype, const nlohmann::json& parsed);

// brief: Typical first among a structural search's tied results (`answer`, a POST /query/csg
//   answer): of results with equal scores, the one whose matched components are nearest the parts
//   their query leaves' words make comes first ("a bored block": the cube with a hole before the
//   slab with one, both a box minus a cylinder). A result's distance is the sum, over its leaf
//   mappings, of descriptorDistance(component, prototype of the leaf's words), size and measures
//   counted only where the leaf's words name them. A leaf's part is made from its words without
//   their article or count and with a plural noun made singular ("the spheres"); a leaf whose
//   words make none counts 0, and so does what a difference cuts away ("a hole", "minus a
//   cylinder": the part it runs through shapes it). Only results that map every query leaf are reordered, in the places
//   they held among their equals (which leaf a partial match maps follows the order of the
//   query's words); only the answer's own results (a tie past the limit is not read).
// note: Reads the tied results' leaf descriptors from `graphs`, the graphs the search matched
//   (built once per shape version; nothing is parsed or described again). Never throws for a
//   result it cannot read (deleted or changed meanwhile, or no mapping): it keeps its place
//   among its equals.
void orderCsgTiesTypicalFirst(const Store& store, StoredGraphCache& graphs, nlohmann::json* answer, size_t maxNodes);

}  // namespace fsdb
