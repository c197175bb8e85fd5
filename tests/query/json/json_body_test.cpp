// query/json/json_body: request-body parsing and typed access with JSON paths.
#include "query/json/json_body.h"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry/core/error.h"

namespace fsdb {
namespace {

using nlohmann::json;

template <class F>
Error errorOf(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error("", "");
}

TEST(JsonBody, ParsesDocumentsWithinTheDepthLimit) {
  EXPECT_EQ(parseJsonBody("{\"a\":[1,2]}", 4)["a"][1], 2);
  EXPECT_EQ(parseJsonBody("[[[1]]]", 3)[0][0][0], 1);
}

TEST(JsonBody, MalformedAndEmptyBodiesAreMalformedJson) {
  Error e = errorOf([] { parseJsonBody("{\"a\":", 8); });
  EXPECT_EQ(e.code(), errc::kMalformedJson);
  EXPECT_EQ(e.path(), "body");
  EXPECT_NE(std::string(e.what()).find("byte"), std::string::npos);
  EXPECT_EQ(errorOf([] { parseJsonBody("", 8); }).code(), errc::kMalformedJson);
}

TEST(JsonBody, NestingBeyondTheLimitIsLimitExceeded) {
  Error e = errorOf([] { parseJsonBody("[[[[1]]]]", 3); });
  EXPECT_EQ(e.code(), errc::kLimitExceeded);
  EXPECT_NE(std::string(e.what()).find("max_json_depth=3"), std::string::npos);
  // A hostile depth far beyond the stack's reach is refused, not a crash.
  std::string deep(200000, '[');
  EXPECT_EQ(errorOf([&] { parseJsonBody(deep, 64); }).code(), errc::kLimitExceeded);
}

// tryParseJsonBody accepts exactly what parseJsonBody accepts, and gives the same document.
TEST(JsonBody, TryParseAcceptsWhatParseAcceptsWithoutErrors) {
  for (const std::string& body :
       std::vector<std::string>{"{\"a\":[1,2]}", "[[[1]]]", "[[[[1]]]]", "0", " \"s\" ", "{\"a\":", "", "[1,]",
                                "{\"n\":1e999}", "1 2", std::string(200000, '['), "{\"a\":{\"b\":{\"c\":1}}}"}) {
    std::optional<json> expected;
    try {
      expected = parseJsonBody(body, 3);
    } catch (const Error&) {
    }
    EXPECT_EQ(tryParseJsonBody(body, 3), expected) << body.substr(0, 40);
  }
}

TEST(JsonBody, TypedAccessNamesThePath) {
  json doc = json::parse(R"({"a":{"b":"x"},"n":1.5,"arr":[1]})");
  EXPECT_EQ(requireNumber(doc["n"], "n"), 1.5);
  EXPECT_EQ(requireString(doc["a"]["b"], "a.b"), "x");
  EXPECT_EQ(requireArray(doc["arr"], "arr").size(), 1u);
  EXPECT_EQ(requireObject(doc["a"], "a").size(), 1u);
  EXPECT_EQ(errorOf([&] { requireNumber(doc["a"], "a"); }).path(), "a");
  EXPECT_EQ(errorOf([&] { requireString(doc["n"], "n"); }).path(), "n");
  EXPECT_EQ(errorOf([&] { requireArray(doc["n"], "n"); }).path(), "n");
  EXPECT_EQ(errorOf([&] { requireObject(doc["arr"], "arr"); }).path(), "arr");
  EXPECT_EQ(errorOf([&] { requireField(doc["a"], "c", "a"); }).path(), "a.c");
  EXPECT_EQ(jsonTypeName(doc["arr"]), "array");
}

// One rule for integer fields: 32 and 32.0 are the integer 32; 2.5, strings, and doubles beyond
// 2^53 are none. optionalInteger follows it.
TEST(JsonBody, IntegralNumbersAreIntegersWrittenEitherWay) {
  EXPECT_EQ(integralNumber(json(32)), 32);
  EXPECT_EQ(integralNumber(json(32.0)), 32);
  EXPECT_EQ(integralNumber(json(-400.0)), -400);
  EXPECT_EQ(integralNumber(json(uint64_t(7))), 7);
  EXPECT_FALSE(integralNumber(json(2.5)));
  EXPECT_FALSE(integralNumber(json("32")));
  EXPECT_FALSE(integralNumber(json(true)));
  EXPECT_FALSE(integralNumber(json(1e300)));
  EXPECT_FALSE(integralNumber(json(std::numeric_limits<uint64_t>::max())));
  EXPECT_EQ(optionalInteger(json{{"limit", 10.0}}, "", "limit", 1, 1, 1000), 10);
  EXPECT_EQ(errorOf([] { optionalInteger(json{{"limit", 10.5}}, "", "limit", 1, 1, 1000); }).path(), "limit");
}

}  // namespace
}  // namespace fsdb
