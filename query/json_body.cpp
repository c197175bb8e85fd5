#include "query/json_body.h"

#include <cmath>

#include "geometry/error.h"
#include "geometry/number_format.h"

namespace fsdb {

nlohmann::json parseJsonBody(const std::string& body, int maxDepth) {
  if (body.empty()) throw Error(errc::kMalformedJson, "request body is empty; expected a JSON document", "body");
  // The parser callback sees the depth of every value; refusing deep nesting here keeps the
  // recursive destructor and every later recursive walk within bounds.
  auto depthGuard = [maxDepth](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > maxDepth)
      throw Error(errc::kLimitExceeded,
                  "JSON nesting deeper than max_json_depth=" + std::to_string(maxDepth), "body");
    return true;
  };
  try {
    return nlohmann::json::parse(body, depthGuard);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(errc::kMalformedJson,
                "body is not valid JSON at byte " + std::to_string(e.byte) + ": " + e.what(), "body");
  }
}

std::string jsonTypeName(const nlohmann::json& j) { return j.type_name(); }

const nlohmann::json& requireObject(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object())
    throw Error(errc::kInvalidDocument, "expected an object, got " + jsonTypeName(j), path);
  return j;
}

const nlohmann::json& requireArray(const nlohmann::json& j, const std::string& path) {
  if (!j.is_array()) throw Error(errc::kInvalidDocument, "expected an array, got " + jsonTypeName(j), path);
  return j;
}

double requireNumber(const nlohmann::json& j, const std::string& path) {
  const std::string what = path.empty() ? "the value" : path;
  if (!j.is_number()) throw Error(errc::kInvalidDocument, what + " must be a number, got " + jsonTypeName(j), path);
  const double v = j.get<double>();
  if (!std::isfinite(v))
    throw Error(errc::kInvalidDocument, what + " must be a finite number, got " + formatNumber(v), path);
  return v;
}

const std::string& requireString(const nlohmann::json& j, const std::string& path) {
  if (!j.is_string()) throw Error(errc::kInvalidDocument, "expected a string, got " + jsonTypeName(j), path);
  return j.get_ref<const std::string&>();
}

const nlohmann::json& requireField(const nlohmann::json& obj, const std::string& key, const std::string& path) {
  requireObject(obj, path);
  auto it = obj.find(key);
  if (it == obj.end()) throw Error(errc::kInvalidDocument, "missing required field '" + key + "'", joinPath(path, key));
  return *it;
}

}  // namespace fsdb
