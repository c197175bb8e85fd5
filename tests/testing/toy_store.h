#pragma once
// A toy database for query/ tests: a ReferenceResolver over name -> (id, document) per kind, with a
// count of lookups.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "query/document/shape_json.h"

namespace fsdb::testing {

// A toy database: name -> (id, document) per kind, and a count of lookups.
struct ToyStore {
  std::map<std::string, std::map<std::string, ResolvedReference>> byName;
  mutable int lookups = 0;
  void add(const std::string& kind, const std::string& name, int64_t id, nlohmann::json doc) {
    byName[kind][name] = {id, std::move(doc)};
  }
  ReferenceResolver resolver() const {
    return [this](const std::string& kind, const nlohmann::json& key) -> std::optional<ResolvedReference> {
      ++lookups;
      auto k = byName.find(kind);
      if (k == byName.end()) return std::nullopt;
      for (const auto& [name, r] : k->second)
        if ((key.is_string() && key == name) || (key.is_number_integer() && key.get<int64_t>() == r.id)) return r;
      return std::nullopt;
    };
  }
};

}  // namespace fsdb::testing
