#pragma once
// Parsing of request bodies. A body that is not JSON is an fsdb::Error with code malformed_json
// and a message that gives the byte offset; nesting deeper than `maxDepth` is limit_exceeded
// (path "body", the limit named) so a hostile document cannot exhaust the stack.
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "query/json/json_path.h"

namespace fsdb {

nlohmann::json parseJsonBody(const std::string& body, int maxDepth);
// brief  parseJsonBody without its errors: nullopt for a body that is not JSON, nests deeper than
//        maxDepth or holds a number beyond double range. No exception is raised, so a caller that
//        only counts failures (a bulk body's unlisted bad lines) pays for none.
std::optional<nlohmann::json> tryParseJsonBody(const std::string& body, int maxDepth);

// Typed access with the JSON path of the value in the error. Each throws fsdb::Error
// (invalid_document) naming `path` and what was expected.
const nlohmann::json& requireObject(const nlohmann::json& j, const std::string& path);
const nlohmann::json& requireArray(const nlohmann::json& j, const std::string& path);
double requireNumber(const nlohmann::json& j, const std::string& path);
const std::string& requireString(const nlohmann::json& j, const std::string& path);
// `j[key]` of an object, or invalid_document "missing required field".
const nlohmann::json& requireField(const nlohmann::json& obj, const std::string& key, const std::string& path);
// invalid_document at path.key for the first key of `obj` not in `known`: "unknown field 'k'"
// + `where` (" in a leaf") + "; expected one of: a, b, c".
void rejectUnknownKeys(const nlohmann::json& obj, const std::string& path, std::initializer_list<const char*> known,
                       const std::string& where = "");
// Optional members of a request object at `path`, the default when absent. Out of range is
// invalid_parameter naming path.key and the range ("limit must be an integer from 1 to 1000, got
// 0"); a value of the wrong type likewise (a boolean of the wrong type is invalid_document).
// Integers may be written 32 or 32.0 (integralNumber).
int64_t optionalInteger(const nlohmann::json& obj, const std::string& path, const std::string& key, int64_t fallback,
                        int64_t min, int64_t max);
// The one rule for integer fields: a JSON number whose value is an integer (32, 32.0, -4e2; not
// 2.5, not a string) within +-2^53 (where doubles still count exactly), else nullopt.
std::optional<int64_t> integralNumber(const nlohmann::json& v);
double optionalNumberIn(const nlohmann::json& obj, const std::string& path, const std::string& key, double fallback,
                        double min, double max);
bool optionalBoolean(const nlohmann::json& obj, const std::string& path, const std::string& key, bool fallback);
// The JSON type name used in messages: "string", "number", "object", ...
std::string jsonTypeName(const nlohmann::json& j);

}  // namespace fsdb
