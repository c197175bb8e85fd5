// See server/service/typical_first.h.
#include "server/service/typical_first.h"

#include <algorithm>
#include <limits>
#include <map>
#include <unordered_map>

#include "geometry/core/error.h"
#include "query/document/part_from_words.h"
#include "query/linguistic/query_tokens.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/descriptor_rows.h"
#include "server/service/stored_graphs.h"

namespace fsdb {

std::optional<std::vector<DescriptorValue>> wordsPrototype(const std::string& text) {
  try {
    return describePart(partFromWords(text, activeVocabulary()));
  } catch (const Error&) {
    return std::nullopt;  // the words make no part: no prototype, ties keep their order
  }
}

namespace {

// The descriptors the meaning names, anywhere in it.
void namedDescriptors(const nlohmann::json& node, std::vector<std::string>* out) {
  if (node.is_object()) {
    if (node.contains("descriptor") && node["descriptor"].is_string()) out->push_back(node["descriptor"].get<std::string>());
    for (const auto& item : node.items()) namedDescriptors(item.value(), out);
  } else if (node.is_array()) {
    for (const nlohmann::json& item : node) namedDescriptors(item, out);
  }
}

// The size and the four measures that a meaning (or a query leaf) does not name: a part's size is
// the noun's default where the words say none, so these are left out of the distance.
std::vector<std::string> unnamedExtents(const nlohmann::json& meaning) {
  std::vector<std::string> named, skip;
  namedDescriptors(meaning, &named);
  for (const char* d : {"size", "length", "width", "thickness", "height"})
    if (std::find(named.begin(), named.end(), d) == named.end()) skip.push_back(d);
  return skip;
}

}  // namespace

std::vector<double> typicalityDistances(const Store& store, const nlohmann::json& results,
                                        const std::vector<DescriptorValue>& prototype, const nlohmann::json& parsed) {
  std::vector<double> out(results.size(), std::numeric_limits<double>::infinity());
  const std::vector<std::string> skip = unnamedExtents(parsed);
  std::map<std::string, std::vector<int64_t>> idsByKind;
  std::unordered_map<int64_t, size_t> at;
  for (size_t i = 0; i < results.size(); ++i) {
    const nlohmann::json& r = results[i];
    if (!r.contains("id") || !r["id"].is_number_integer() || !r.contains("kind") || !r["kind"].is_string()) continue;
    const int64_t id = r["id"].get<int64_t>();
    if (!at.emplace(id, i).second) continue;
    idsByKind[r["kind"].get<std::string>()].push_back(id);
  }
  for (const auto& [kind, ids] : idsByKind)
    for (const IndexedObject& o : store.indexedObjects(kind, ids)) {
      if (o.pending) continue;
      double best = std::numeric_limits<double>::infinity();
      for (const auto& [component, values] : o.components)
        best = std::min(best, descriptorDistance(decodeDescriptorValues(values), prototype, skip));
      // The words describe one part: a whole of several, one of which fits, is a less typical
      // instance of them than a part that is one. Each other component counts a whole degree.
      if (!o.components.empty()) best += static_cast<double>(o.components.size() - 1);
      out[at.at(o.id)] = best;
    }
  return out;
}

namespace {

// The part a query leaf's words make, read as a part's words are: without the article or count
// the phrase put before them ("the very bent cylinder", "two spheres") and with a plural noun at
// the end made singular ("spheres"), so that a text and its read_as form, or its synonyms, make
// the same part. nullopt where they make none ("bored", a hole's words).
std::optional<std::vector<DescriptorValue>> leafPrototype(const std::string& text) {
  const Vocabulary& v = activeVocabulary();
  std::vector<std::string> words;
  try {
    for (const query_tokens::Token& t : query_tokens::tokenize(text, 0, text.size())) words.push_back(t.text);
  } catch (const Error&) {
    return std::nullopt;  // a character no query tokenises: no words to make a part of
  }
  static const std::vector<std::string> kLeading = {"a", "an", "the", "its", "one", "two", "three", "four",
                                                    "five", "six", "seven", "eight", "nine", "ten"};
  size_t first = 0;
  while (first < words.size() && std::find(kLeading.begin(), kLeading.end(), words[first]) != kLeading.end()) ++first;
  if (first == words.size()) return std::nullopt;
  if (const Noun* noun = v.noun(words.back())) words.back() = noun->word;
  std::string phrase;
  for (size_t i = first; i < words.size(); ++i) phrase += (phrase.empty() ? "" : " ") + words[i];
  return wordsPrototype(phrase);
}

// The query leaves of a parsed CSG tree by path ("tree", "tree.children[1]", ...), as their words,
// each with whether it cuts (a difference's second or later operand, or below one).
struct QueryLeaf {
  const nlohmann::json* node;
  bool cutter;
};
void queryLeaves(const nlohmann::json& node, const std::string& path, bool cutter, std::map<std::string, QueryLeaf>* out) {
  if (!node.is_object()) return;
  if (node.contains("children") && node["children"].is_array()) {
    const bool difference = node.value("op", "") == "difference";
    for (size_t i = 0; i < node["children"].size(); ++i)
      queryLeaves(node["children"][i], path + ".children[" + std::to_string(i) + "]", cutter || (difference && i > 0), out);
    return;
  }
  if (node.contains("text") && node["text"].is_string()) (*out)[path] = {&node, cutter};
}

}  // namespace

void orderCsgTiesTypicalFirst(const Store& store, StoredGraphCache& graphs, nlohmann::json* answer, size_t maxNodes) {
  if (!answer->contains("results") || !(*answer)["results"].is_array()) return;
  nlohmann::json& results = (*answer)["results"];
  std::vector<double> scores;
  for (const nlohmann::json& r : results) scores.push_back(r.value("score", 0.0));
  std::vector<double> sorted = scores;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;
  // Each query leaf's prototype and the descriptors its words name.
  const nlohmann::json parsed = answer->value("parsed", nlohmann::json::object());
  std::map<std::string, QueryLeaf> leaves;
  if (parsed.contains("tree")) queryLeaves(parsed["tree"], "tree", false, &leaves);
  struct Prototype {
    std::vector<DescriptorValue> values;
    std::vector<std::string> skip;
  };
  std::map<std::string, Prototype> prototypes;
  for (const auto& [path, leaf] : leaves) {
    // What a part cuts away is shaped by the part ("a hole" runs through it, "minus a cylinder"
    // alike): it is no free-standing thing of its noun, so only the material's leaves count.
    if (leaf.cutter) continue;
    std::optional<std::vector<DescriptorValue>> prototype = leafPrototype((*leaf.node)["text"].get<std::string>());
    if (!prototype) continue;
    prototypes.emplace(path, Prototype{std::move(*prototype), unnamedExtents(*leaf.node)});
  }
  if (prototypes.empty()) return;
  std::vector<double> distance(results.size(), 0.0);
  // Only results that map every query leaf are compared: which leaf a partial match maps is the
  // order of the query's words, and "a cone on top of a cylinder on top of a box" must rank as
  // its read_as form, "the union of the box and the cylinder to its top and the cone to its top".
  std::vector<bool> whole(results.size(), false);
  std::shared_ptr<const StoreVersions> versions;  // read once, at the first tie
  for (size_t i = 0; i < results.size(); ++i) {
    const nlohmann::json& r = results[i];
    const bool tied = std::count(scores.begin(), scores.end(), scores[i]) > 1;
    if (!tied || !r.contains("id") || !r["id"].is_number_integer() || !r.contains("mapping")) continue;
    size_t mapped = 0;
    for (const nlohmann::json& m : r["mapping"]) mapped += m.value("op", "") == "leaf" ? 1 : 0;
    if (mapped != leaves.size()) continue;
    whole[i] = true;
    // The graph the search matched (the cache's, its leaves described once): the mapping's
    // stored nodes are its nodes.
    // A shape changed since the search has the nodes of its new version: a mapping past them is
    // skipped below, and the order of ties is all that reads them.
    std::shared_ptr<const StoredGraph> graph;
    try {
      if (!versions) versions = graphs.versions(store);
      const int64_t id = r["id"].get<int64_t>();
      const auto latest = versions->latest.find(id);
      if (latest == versions->latest.end()) continue;  // deleted meanwhile: keeps its place
      graph = graphs.graph(store, ObjectVersion{id, "", latest->second}, *versions, maxNodes);
    } catch (const Error&) {
      continue;  // deleted meanwhile, or past the limits: keeps its place
    }
    const std::vector<CsgGraphNode>& nodes = graph->shape.graph.nodes;
    for (const nlohmann::json& m : r["mapping"]) {
      if (m.value("op", "") != "leaf") continue;
      const auto prototype = prototypes.find(m.value("query_path", ""));
      const int node = m.value("stored_node", -1);
      if (prototype == prototypes.end() || node < 0 || static_cast<size_t>(node) >= nodes.size()) continue;
      const int leaf = nodes[static_cast<size_t>(node)].leaf;
      if (leaf < 0 || static_cast<size_t>(leaf) >= graph->leafDescriptors.size()) continue;
      distance[i] += descriptorDistance(graph->leafDescriptors[static_cast<size_t>(leaf)], prototype->second.values,
                                        prototype->second.skip);
    }
  }
  std::vector<size_t> order(results.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Within each run of equal scores, the results that map every leaf typical first, in the places
  // they held; the others keep theirs.
  for (size_t from = 0; from < order.size();) {
    size_t to = from;
    while (to < order.size() && scores[to] == scores[from]) ++to;
    std::vector<size_t> places, members;
    for (size_t k = from; k < to; ++k)
      if (whole[k]) {
        places.push_back(k);
        members.push_back(k);
      }
    std::stable_sort(members.begin(), members.end(), [&](size_t a, size_t b) { return distance[a] < distance[b]; });
    for (size_t k = 0; k < places.size(); ++k) order[places[k]] = members[k];
    from = to;
  }
  nlohmann::json ranked = nlohmann::json::array();
  for (size_t i : order) ranked.push_back(std::move(results[i]));
  results = std::move(ranked);
}

}  // namespace fsdb
