// Fuzz target: the query-string parameters of the GET routes, and the JSON request members read
// by the same kind of helpers.
//
// The input is a query string (a leading '?' is dropped). cpp-httplib's own parser
// (httplib::detail::parse_query_text, what the server runs on every request target: split at '&'
// and '=', percent- and '+'-decoding) fills an httplib::Request, and an fsdb::ApiRequest over it
// feeds the public helpers of server/http/api.h.
//
// Covered (reachable from here):
//  * positiveInteger (every {id} path segment, ?version=, ?after=, ?limit=, ?batch=): on every
//    decoded value and key, with and without a maximum;
//  * numberParam (?x=, ?y=, ?z=, ?alpha=, ?resolution=, ?size=, ?candidate=, ?samples=), with and
//    without a fallback;
//  * versionParam (?version=);
//  * the typed members of query/json/json_body.h (integralNumber, optionalInteger,
//    optionalNumberIn, optionalBoolean), on an object whose members are the decoded parameters, each
//    value read as JSON when it parses (depth 16) and as a string otherwise.
// Not reachable (anonymous namespaces or inline in route handlers, so not fuzzed here):
// booleanParam and the If-Match parsing of server/http/objects_api.cpp, countParam and alphaParam
// of server/http/bezier_api.cpp, and the inline checks of ?bound=, ?format=, ?mode= and ?name=.
//
// Properties: positiveInteger accepts exactly 1 to 18 ASCII digits with a value from 1 to the
// maximum and returns that value; numberParam returns the fallback for an absent parameter and
// otherwise accepts exactly a text that strtod reads whole (every byte of the decoded value) to a
// finite number, and returns that number; versionParam is absent exactly without ?version= and
// otherwise positiveInteger up to INT32_MAX; the json_body helpers return the fallback for an
// absent member and otherwise a value of the member within the range asked for.
#include <httplib.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

#include "geometry/core/error.h"
#include "query/json/json_body.h"
#include "server/http/api.h"
#include "server/http/http_server.h"
#include "tests/fuzz/fuzz_check.h"

namespace {

constexpr int kDepth = 16;

// What positiveInteger should say: the value, or -1 for a refusal.
int64_t expectedPositive(const std::string& text, int64_t max) {
  if (text.empty() || text.size() > 18) return -1;
  int64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return -1;
    v = v * 10 + (c - '0');
  }
  return v >= 1 && v <= max ? v : -1;
}

void checkPositive(const std::string& text, int64_t max) {
  const int64_t expected = expectedPositive(text, max);
  try {
    const int64_t v = fsdb::positiveInteger(text, "id", max);
    FUZZ_CHECK(expected == v, "positiveInteger accepts 1 to 18 digits from 1 to max, as their value");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(expected == -1, "positiveInteger refuses only what is no positive integer up to max");
    FUZZ_CHECK(e.code() == fsdb::errc::kInvalidParameter && e.path() == "id", "a refusal names the parameter");
  }
}

void checkNumber(const fsdb::ApiRequest& req, const std::string& name) {
  const bool present = req.hasQueryParam(name);
  const std::string text = req.queryParam(name);
  // strtod over the whole decoded value: every byte read, the result finite.
  bool readsWhole = false;
  double expected = 0.0;
  if (present && !text.empty()) {
    char* end = nullptr;
    expected = std::strtod(text.c_str(), &end);
    readsWhole = end == text.c_str() + text.size() && std::isfinite(expected);
  }
  try {
    const double v = fsdb::numberParam(req, name, 0.25);
    if (!present) {
      FUZZ_CHECK(v == 0.25, "an absent parameter gives the fallback");
    } else {
      FUZZ_CHECK(readsWhole, "numberParam accepts only a text that is a finite number, every byte of it");
      FUZZ_CHECK(v == expected || (std::isnan(v) && std::isnan(expected)), "numberParam returns the number");
    }
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(present && !readsWhole, "numberParam refuses only a text that is no finite number");
    FUZZ_CHECK(e.code() == fsdb::errc::kInvalidParameter && e.path() == name, "a refusal names the parameter");
  }
  try {
    const double v = fsdb::numberParam(req, name, std::nullopt);
    FUZZ_CHECK(present && std::isfinite(v), "without a fallback only a present parameter is a number");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(!present || !readsWhole, "without a fallback the same verdict");
  }
}

void checkJsonMembers(const nlohmann::json& obj, const std::string& key) {
  const bool present = obj.contains(key);
  if (present) {
    const nlohmann::json& v = obj[key];
    if (const std::optional<int64_t> n = fsdb::integralNumber(v)) {
      FUZZ_CHECK(v.is_number(), "an integral number is a number");
      FUZZ_CHECK(*n >= -(int64_t(1) << 53) && *n <= (int64_t(1) << 53), "an integral number is within 2^53");
      FUZZ_CHECK(static_cast<double>(*n) == v.get<double>(), "an integral number has the member's value");
    }
  }
  try {
    const int64_t n = fsdb::optionalInteger(obj, "query", key, 7, 1, 1000);
    FUZZ_CHECK(present ? (n >= 1 && n <= 1000 && fsdb::integralNumber(obj[key]) == n) : n == 7,
               "optionalInteger: the fallback, or the member's integer within the range");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(present, "an absent member is never refused");
  }
  try {
    const double x = fsdb::optionalNumberIn(obj, "query", key, 0.5, 0.0, 1.0);
    FUZZ_CHECK(present ? (x >= 0.0 && x <= 1.0 && x == obj[key].get<double>()) : x == 0.5,
               "optionalNumberIn: the fallback, or the member's number within the range");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(present, "an absent member is never refused");
  }
  try {
    const bool b = fsdb::optionalBoolean(obj, "query", key, true);
    FUZZ_CHECK(present ? (obj[key].is_boolean() && b == obj[key].get<bool>()) : b,
               "optionalBoolean: the fallback, or the member's boolean");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(present && !obj[key].is_boolean(), "optionalBoolean refuses only a member that is no boolean");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 64 * 1024) return 0;
  std::string query(reinterpret_cast<const char*>(data), size);
  if (!query.empty() && query[0] == '?') query.erase(0, 1);

  httplib::Request raw;
  httplib::detail::parse_query_text(query, raw.params);
  const fsdb::ApiRequest req{raw, nullptr, {}, {}};

  std::set<std::string> names = {"id", "version", "after",      "limit", "batch",     "x",       "y",
                                 "z",  "alpha",   "resolution", "size",  "candidate", "samples", "absent"};
  nlohmann::json members = nlohmann::json::object();
  for (const auto& [key, value] : raw.params) {
    names.insert(key);
    checkPositive(key, INT64_MAX);
    checkPositive(value, INT64_MAX);
    checkPositive(value, 1000);
    if (!members.contains(key)) {
      std::optional<nlohmann::json> parsed = fsdb::tryParseJsonBody(value, kDepth);
      // A value that is no JSON is a string member; as in a parsed body, its text is valid UTF-8
      // (a request body's strings always are: nlohmann's parser refuses any other).
      members[key] = parsed ? std::move(*parsed)
                            : nlohmann::json::parse(
                                  nlohmann::json(value).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    }
  }
  for (const std::string& name : names) {
    checkNumber(req, name);
    checkJsonMembers(members, name);
  }

  try {
    const std::optional<int> version = fsdb::versionParam(req);
    FUZZ_CHECK(version.has_value() == req.hasQueryParam("version"), "a version exactly when ?version= is given");
    if (version) FUZZ_CHECK(*version == expectedPositive(req.queryParam("version"), INT32_MAX), "the version given");
  } catch (const fsdb::Error& e) {
    FUZZ_CHECK(req.hasQueryParam("version") && expectedPositive(req.queryParam("version"), INT32_MAX) == -1,
               "versionParam refuses only a version that is no positive integer up to 2^31 - 1");
  }
  return 0;
}
