#pragma once
// JSON form of the operators of geometry/operators/operator_catalog.h (Li & Tian; Li).
//
// An operator is an object: its name and its parameters as sibling keys, a nested step function
// under "step" for the blends:
//   {"name":"zadeh"}  {"name":"yager","k":2}  {"name":"smooth_and","n":2,"delta":0.5}
//   {"name":"ext_max","delta":0.5,"epsilon":0.25,"step":{"name":"bspline","m":3}}
// Parsing validates against the catalogue and fills defaults; errors carry the JSON path
// ("operator.delta", "tree.children[1].operator.step.n").
#include <nlohmann/json.hpp>
#include <string>

#include "geometry/operators/operator_catalog.h"

namespace fsdb {

OperatorConfig parseOperatorConfig(const nlohmann::json& j, const std::string& path);
nlohmann::json operatorConfigToJson(const OperatorConfig& config);
// One catalogue entry as served by GET /operators (infinite bounds become null).
nlohmann::json operatorSpecToJson(const OperatorSpec& spec);
// "intersection" | "union" | "difference".
Combine parseCombine(const nlohmann::json& j, const std::string& path);
const char* combineName(Combine c);

}  // namespace fsdb
