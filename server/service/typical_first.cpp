// See server/service/typical_first.h.
#include "server/service/typical_first.h"

#include <algorithm>
#include <limits>
#include <map>
#include <unordered_map>

#include "geometry/core/error.h"
#include "query/document/part_from_words.h"
#include "query/linguistic/vocabulary.h"
#include "server/service/descriptor_rows.h"

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

}  // namespace

std::vector<double> typicalityDistances(const Store& store, const nlohmann::json& results,
                                        const std::vector<DescriptorValue>& prototype, const nlohmann::json& parsed) {
  std::vector<double> out(results.size(), std::numeric_limits<double>::infinity());
  std::vector<std::string> named, skip;
  namedDescriptors(parsed, &named);
  for (const char* d : {"size", "length", "width", "thickness", "height"})
    if (std::find(named.begin(), named.end(), d) == named.end()) skip.push_back(d);
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

}  // namespace fsdb
