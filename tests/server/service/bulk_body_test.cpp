// server/service/bulk_body: the two body forms of a bulk import read a document at a time, with
// the line numbers and the whole-body errors a parse of the whole body gives.
#include "server/service/bulk_body.h"

#include <gtest/gtest.h>

#include "geometry/core/error.h"
#include "query/json/json_body.h"

namespace fsdb {
namespace {

using nlohmann::json;

std::vector<std::string> texts(const std::string& body) {
  BulkBodyReader reader(body, 64);
  std::vector<std::string> out;
  LineSpan span;
  while (reader.next(span))
    out.push_back(std::to_string(span.line) + ":" + body.substr(span.begin, span.end - span.begin));
  EXPECT_EQ(out.size(), reader.count()) << body;
  EXPECT_FALSE(reader.next(span));  // stays at the end
  return out;
}

std::string errorCode(const std::string& body, int depth = 64) {
  try {
    BulkBodyReader reader(body, depth);
  } catch (const Error& e) {
    return e.code() + " " + e.path();
  }
  return "";
}

TEST(BulkBodyReader, JsonLinesAreTheNonBlankLinesWithTheirFileNumbers) {
  EXPECT_EQ(texts("a\n\n \t\r\nbb\r\n  c"), (std::vector<std::string>{"1:a", "4:bb\r", "5:  c"}));
  EXPECT_EQ(texts("x\n"), std::vector<std::string>{"1:x"});
  EXPECT_TRUE(texts("").empty());
  EXPECT_TRUE(texts("\n \n").empty());
  // A line that is not JSON is still a line: its error is its own (parseBulkLine).
  EXPECT_EQ(texts("{not json\n[1"), (std::vector<std::string>{"1:{not json", "2:[1"}));
}

TEST(BulkBodyReader, AnArrayIsOneDocumentPerElementWhateverItsStringsHold) {
  const std::string body = " [ {\"a\":\"x,]}\\\"[\"} ,\n[1,[2]],\t3 , \"s\\\\\",{} ]\n";
  EXPECT_EQ(texts(body),
            (std::vector<std::string>{"1:{\"a\":\"x,]}\\\"[\"}", "2:[1,[2]]", "3:3", "4:\"s\\\\\"", "5:{}"}));
  EXPECT_TRUE(texts("[]").empty());
  EXPECT_TRUE(texts(" [ \n ] ").empty());
  // Each element parses to what the whole array holds at its place.
  const json whole = json::parse(body);
  BulkBodyReader reader(body, 64);
  LineSpan span;
  for (size_t i = 0; reader.next(span); ++i) EXPECT_EQ(parseBulkLine(body, span, 64).document, whole[i]);
}

TEST(BulkBodyReader, AMalformedArrayIsOneErrorForTheWholeBodyAsParseJsonBodyGives) {
  for (const std::string body : {"[1, 2", "[1,,2]", "[1,2,]", "[1] [2]", "[{\"a\":1}, {bad}]", "[\"x]"}) {
    EXPECT_EQ(errorCode(body), "malformed_json body") << body;
    std::string expected;
    try {
      parseJsonBody(body, 64);
    } catch (const Error& e) {
      expected = e.what();
    }
    try {
      BulkBodyReader reader(body, 64);
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), expected) << body;
    }
  }
  // Nesting beyond the limit, counted in the whole body as parseJsonBody counts it.
  EXPECT_EQ(errorCode("[[[1]]]", 2), "limit_exceeded body");
  EXPECT_EQ(errorCode("[[[1]]]", 3), "");
  EXPECT_THROW(parseJsonBody("[[[1]]]", 2), Error);
  EXPECT_NO_THROW(parseJsonBody("[[[1]]]", 3));
  // A number beyond double range names where it is, as parseJsonBody does.
  EXPECT_EQ(errorCode(R"([{"a":1}, {"params":{"a1":1e999}}])"), "invalid_document [1].params.a1");
}

TEST(ParseBulkLine, RecordsTheLinesErrorInsteadOfThrowing) {
  const std::string body = "{\"a\":1}\nnope";
  const BulkLine good = parseBulkLine(body, {1, 0, 7}, 64);
  EXPECT_EQ(good.document, json({{"a", 1}}));
  EXPECT_TRUE(good.parseError.is_null());
  const BulkLine bad = parseBulkLine(body, {2, 8, 12}, 64);
  EXPECT_EQ(bad.line, 2u);
  EXPECT_TRUE(bad.document.is_null());
  EXPECT_EQ(bad.parseError["code"], "malformed_json");
  EXPECT_EQ(parseBulkLine("[[1]]", {1, 0, 5}, 1).parseError["code"], "limit_exceeded");
}

TEST(SplitBulkBody, JsonLinesKeepFileLineNumbersAndRecordBadLines) {
  const std::string a = R"({"name":"a"})", b = R"({"name":"b"})";
  const auto lines = splitBulkBody(a + "\n\n  \nnot json\n" + b, 64);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].line, 1u);
  EXPECT_EQ(lines[1].line, 4u);
  EXPECT_EQ(lines[1].parseError["code"], "malformed_json");
  EXPECT_EQ(lines[2].line, 5u);
  EXPECT_EQ(lines[2].document["name"], "b");
}

TEST(SplitBulkBody, AJsonArrayIsOneDocumentPerElement) {
  const auto lines = splitBulkBody(R"(  [{"name":"a"},{"name":"b"}])", 64);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1].line, 2u);
  EXPECT_EQ(lines[1].document["name"], "b");
  EXPECT_THROW(splitBulkBody("[1, 2", 64), Error);
  EXPECT_TRUE(splitBulkBody("", 64).empty());
}

TEST(IsJsonArrayBody, TheFirstNonBlankByteDecides) {
  EXPECT_TRUE(isJsonArrayBody(" \n[1]"));
  EXPECT_FALSE(isJsonArrayBody("{\"a\":[1]}"));
  EXPECT_FALSE(isJsonArrayBody(""));
}

}  // namespace
}  // namespace fsdb
