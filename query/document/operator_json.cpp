#include "query/document/operator_json.h"

#include <cmath>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "query/json/json_body.h"

namespace fsdb {

OperatorConfig parseOperatorConfig(const nlohmann::json& j, const std::string& path) {
  requireObject(j, path);
  OperatorConfig config;
  config.name = requireString(requireField(j, "name", path), joinPath(path, "name"));
  const OperatorSpec* spec = findOperator(config.name);
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    if (key == "name") continue;
    const std::string keyPath = joinPath(path, key);
    if (key == "step" && spec && spec->takesStep) {
      config.step.push_back(parseOperatorConfig(it.value(), keyPath));
      continue;
    }
    if (!it.value().is_number())
      throw Error(errc::kInvalidParameter,
                  "parameter '" + key + "' must be a number, got " + jsonTypeName(it.value()), keyPath);
    config.params[key] = it.value().get<double>();
  }
  try {
    return validateOperator(config);
  } catch (const Error& e) {
    throw e.withPathPrefix(path);
  }
}

nlohmann::json operatorConfigToJson(const OperatorConfig& config) {
  nlohmann::json j = {{"name", config.name}};
  const OperatorSpec* spec = findOperator(config.name);
  for (const auto& [name, value] : config.params) {
    // Integer parameters (degrees n, m) go out as JSON integers: clients compare them with the
    // integers they sent, and "n": 3.0 would read as a different type in typed languages.
    bool integer = false;
    if (spec)
      for (const ParamSpec& p : spec->params) integer = integer || (p.name == name && p.integer);
    if (integer) j[name] = static_cast<long long>(value);
    else j[name] = value;
  }
  if (!config.step.empty()) j["step"] = operatorConfigToJson(config.step.front());
  return j;
}

nlohmann::json operatorSpecToJson(const OperatorSpec& spec) {
  nlohmann::json params = nlohmann::json::array();
  auto bound = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  for (const ParamSpec& p : spec.params) {
    params.push_back({{"name", p.name},
                      {"min", bound(p.min)},
                      {"max", bound(p.max)},
                      {"min_inclusive", p.minInclusive},
                      {"max_inclusive", p.maxInclusive},
                      {"default", p.defaultValue},
                      {"integer", p.integer},
                      {"description", p.description}});
  }
  nlohmann::json j = {{"name", spec.name},
                      {"kind", spec.kind},
                      {"arity", spec.arity},
                      {"params", params},
                      {"takes_step", spec.takesStep},
                      {"reference", spec.reference},
                      {"formula", spec.formula},
                      {"description", spec.description}};
  return j;
}

Combine parseCombine(const nlohmann::json& j, const std::string& path) {
  const std::string& s = requireString(j, path);
  if (s == "intersection") return Combine::Intersection;
  if (s == "union") return Combine::Union;
  if (s == "difference") return Combine::Difference;
  throw Error(errc::kInvalidParameter,
              "unknown combination '" + quotedWord(s) + "'; expected intersection, union or difference", path);
}

const char* combineName(Combine c) {
  switch (c) {
    case Combine::Intersection: return "intersection";
    case Combine::Union: return "union";
    case Combine::Difference: return "difference";
  }
  return "?";
}

}  // namespace fsdb
