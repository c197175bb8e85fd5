#include "query/json/json_body.h"

#include <cmath>
#include <vector>

#include "geometry/core/closest_names.h"
#include "geometry/core/error.h"
#include "geometry/core/number_format.h"
#include "query/json/json_path.h"

namespace fsdb {

namespace {

// Feeds the parser callback's events to the tracker: where the parser is, for errors the parser
// itself raises on a value (a number literal beyond double range such as 1e999).
void track(JsonPathTracker& position, nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
  using E = nlohmann::json::parse_event_t;
  switch (event) {
    case E::object_start: position.openObject(); break;
    case E::array_start: position.openArray(); break;
    case E::key:
      if (parsed.is_string()) position.key(parsed.get<std::string>());
      break;
    case E::object_end:
    case E::array_end: position.close(); break;
    case E::value: position.valueDone(); break;
  }
}

}  // namespace

nlohmann::json parseJsonBody(const std::string& body, int maxDepth) {
  if (body.empty()) throw Error(errc::kMalformedJson, "request body is empty; expected a JSON document", "body");
  // The parser callback sees the depth of every value; refusing deep nesting here keeps the
  // recursive destructor and every later recursive walk within bounds.
  JsonPathTracker position;
  auto depthGuard = [maxDepth, &position](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    if (depth > maxDepth)
      throw Error(errc::kLimitExceeded, "JSON nesting deeper than max_json_depth=" + std::to_string(maxDepth), "body");
    track(position, event, parsed);
    return true;
  };
  try {
    return nlohmann::json::parse(body, depthGuard);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(errc::kMalformedJson, "body is not valid JSON at byte " + std::to_string(e.byte) + ": " + e.what(),
                "body");
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: a number literal beyond double range (1e999): not finite, like NaN (docs/api.md §2).
    throw Error(errc::kInvalidDocument, std::string("a number must be finite: ") + e.what(), position.path());
  }
}

std::optional<nlohmann::json> tryParseJsonBody(const std::string& body, int maxDepth) {
  bool tooDeep = false;
  // Returning false drops the value; the parser goes on (iteratively) to the end of the body.
  auto depthGuard = [maxDepth, &tooDeep](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    tooDeep = tooDeep || depth > maxDepth;
    return !tooDeep;
  };
  nlohmann::json parsed = nlohmann::json::parse(body, depthGuard, /*allow_exceptions=*/false);
  if (tooDeep || parsed.is_discarded()) return std::nullopt;
  return parsed;
}

std::string jsonTypeName(const nlohmann::json& j) { return j.type_name(); }

const nlohmann::json& requireObject(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw Error(errc::kInvalidDocument, "expected an object, got " + jsonTypeName(j), path);
  return j;
}

const nlohmann::json& requireArray(const nlohmann::json& j, const std::string& path) {
  if (!j.is_array()) throw Error(errc::kInvalidDocument, "expected an array, got " + jsonTypeName(j), path);
  return j;
}

int64_t optionalInteger(const nlohmann::json& obj, const std::string& path, const std::string& key, int64_t fallback,
                        int64_t min, int64_t max) {
  if (!obj.contains(key)) return fallback;
  const nlohmann::json& v = obj[key];
  const std::optional<int64_t> n = integralNumber(v);
  if (!n || *n < min || *n > max)
    throw Error(errc::kInvalidParameter,
                key + " must be an integer from " + std::to_string(min) + " to " + std::to_string(max) + ", got " +
                    v.dump(),
                joinPath(path, key));
  return *n;
}

std::optional<int64_t> integralNumber(const nlohmann::json& v) {
  constexpr double kExact = 9007199254740992.0;  // 2^53
  if (v.is_number_unsigned())
    return v.get<uint64_t>() <= uint64_t(kExact) ? std::optional<int64_t>(int64_t(v.get<uint64_t>())) : std::nullopt;
  if (v.is_number_integer()) {
    const int64_t n = v.get<int64_t>();
    return n >= -int64_t(kExact) && n <= int64_t(kExact) ? std::optional<int64_t>(n) : std::nullopt;
  }
  if (!v.is_number_float()) return std::nullopt;
  const double x = v.get<double>();
  if (!(x >= -kExact && x <= kExact) || x != std::floor(x)) return std::nullopt;
  return static_cast<int64_t>(x);
}

double optionalNumberIn(const nlohmann::json& obj, const std::string& path, const std::string& key, double fallback,
                        double min, double max) {
  if (!obj.contains(key)) return fallback;
  const nlohmann::json& v = obj[key];
  const double x = requireNumber(v, joinPath(path, key));
  if (!(x >= min && x <= max)) {
    throw Error(errc::kInvalidParameter,
                key + " must be in [" + formatNumber(min) + ", " + formatNumber(max) + "], got " + v.dump(),
                joinPath(path, key));
  }
  return x;
}

bool optionalBoolean(const nlohmann::json& obj, const std::string& path, const std::string& key, bool fallback) {
  if (!obj.contains(key)) return fallback;
  const nlohmann::json& v = obj[key];
  if (!v.is_boolean())
    throw Error(errc::kInvalidDocument, key + " must be a boolean, got " + jsonTypeName(v), joinPath(path, key));
  return v.get<bool>();
}

void rejectUnknownKeys(const nlohmann::json& obj, const std::string& path, std::initializer_list<const char*> known,
                       const std::string& where) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    std::string list;
    for (const char* k : known) {
      ok = ok || it.key() == k;
      list += (list.empty() ? "" : ", ") + std::string(k);
    }
    if (!ok)
      throw Error(errc::kInvalidDocument, "unknown field '" + quotedWord(it.key()) + "'" + where + "; expected one of: " + list,
                  joinPath(path, it.key()));
  }
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
