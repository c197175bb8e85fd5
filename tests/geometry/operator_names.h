#pragma once
// The binary operators of the catalogue (geometry/operators/operator_catalog.h) for the node tests.
#include <string>
#include <vector>

#include "geometry/operators/operator_catalog.h"

// Every fuzzy_operator and blend of the catalogue, zadeh included.
inline std::vector<std::string> binaryOperatorNames() {
  std::vector<std::string> names;
  for (const fsdb::OperatorSpec& spec : fsdb::operatorCatalog())
    if (spec.kind == "fuzzy_operator" || spec.kind == "blend") names.push_back(spec.name);
  return names;
}
