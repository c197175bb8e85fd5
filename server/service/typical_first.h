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

}  // namespace fsdb
