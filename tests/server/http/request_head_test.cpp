// scanRequestHead and chunkedBodyBytes (server/http/request_head.h): where a request's head and
// body end in the bytes received so far.
#include "server/http/request_head.h"

#include <gtest/gtest.h>

namespace fsdb {
namespace {

TEST(RequestHead, NothingUntilTheBlankLine) {
  EXPECT_FALSE(scanRequestHead(""));
  EXPECT_FALSE(scanRequestHead("GET / HTTP/1.1\r\nHost: x\r\n"));
  EXPECT_FALSE(scanRequestHead("GET / HTTP/1.1\r\nHost: x\r\n\r"));
  const std::string whole = "GET /parts/3?x=1#f HTTP/1.1\r\nHost: x\r\n\r\nleft";
  const auto head = scanRequestHead(whole);
  ASSERT_TRUE(head);
  EXPECT_EQ(head->method, "GET");
  EXPECT_EQ(head->target, "/parts/3?x=1#f");
  EXPECT_EQ(head->path(), "/parts/3");
  EXPECT_EQ(head->headBytes, whole.size() - 4);
  EXPECT_FALSE(head->contentLength);
  EXPECT_FALSE(head->chunked);
  EXPECT_FALSE(head->expectContinue);
}

TEST(RequestHead, SearchFromFindsABlankLineSplitAcrossReads) {
  const std::string first = "GET / HTTP/1.1\r\nHost: x\r\n\r";
  EXPECT_FALSE(scanRequestHead(first));
  const auto head = scanRequestHead(first + "\n", first.size());
  ASSERT_TRUE(head);
  EXPECT_EQ(head->headBytes, first.size() + 1);
}

TEST(RequestHead, HeadersAreTrimmedAndFoundInAnyCase) {
  const auto head = scanRequestHead("POST /q HTTP/1.1\r\ncontent-LENGTH:  12 \r\nAuthorization: Bearer t\r\n\r\n");
  ASSERT_TRUE(head);
  ASSERT_TRUE(head->contentLength);
  EXPECT_EQ(*head->contentLength, 12u);
  EXPECT_EQ(head->header("authorization"), "Bearer t");
  EXPECT_EQ(head->header("X-None"), "");
}

TEST(RequestHead, UnreadableOrConflictingLengthsAreMarked) {
  for (const char* bad : {"-1", "1 2", "0x10", "", "99999999999999999999", "12, 13"}) {
    const auto head = scanRequestHead(std::string("POST / HTTP/1.1\r\nContent-Length: ") + bad + "\r\n\r\n");
    ASSERT_TRUE(head);
    EXPECT_TRUE(head->bodyLengthInvalid) << bad;
  }
  const auto two = scanRequestHead("POST / HTTP/1.1\r\nContent-Length: 3\r\nContent-Length: 4\r\n\r\n");
  ASSERT_TRUE(two);
  EXPECT_TRUE(two->bodyLengthInvalid);
  const auto same = scanRequestHead("POST / HTTP/1.1\r\nContent-Length: 3\r\nContent-Length: 3\r\n\r\n");
  ASSERT_TRUE(same);
  EXPECT_FALSE(same->bodyLengthInvalid);
}

TEST(RequestHead, ChunkedAndExpectContinue) {
  const std::string text =
      "POST / HTTP/1.1\r\nTransfer-Encoding: gzip, Chunked\r\nExpect: 100-Continue\r\nHost: x\r\n\r\n";
  const auto head = scanRequestHead(text);
  ASSERT_TRUE(head);
  EXPECT_TRUE(head->chunked);
  ASSERT_TRUE(head->expectContinue);
  EXPECT_EQ(text.substr(head->expectBegin, head->expectEnd - head->expectBegin), "Expect: 100-Continue\r\n");
  const auto other = scanRequestHead("POST / HTTP/1.1\r\nExpect: something-else\r\n\r\n");
  ASSERT_TRUE(other);
  EXPECT_FALSE(other->expectContinue);
}

TEST(ChunkedBody, EndsAfterTheLastChunkAndTrailer) {
  const std::string body = "3\r\nabc\r\n10;name=v\r\n0123456789abcdef\r\n0\r\n\r\n";
  ASSERT_TRUE(chunkedBodyBytes(body));
  EXPECT_EQ(*chunkedBodyBytes(body), body.size());
  EXPECT_EQ(*chunkedBodyBytes(body + "GET /next"), body.size());
  const std::string trailer = "1\r\nx\r\n0\r\nX-Sum: 1\r\n\r\n";
  EXPECT_EQ(*chunkedBodyBytes(trailer), trailer.size());
  for (size_t cut = 0; cut < body.size(); ++cut) EXPECT_FALSE(chunkedBodyBytes(body.substr(0, cut))) << cut;
}

TEST(ChunkedBody, AMalformedSizeEndsTheScan) {
  EXPECT_EQ(*chunkedBodyBytes("zz\r\nabc"), 4u);
  EXPECT_EQ(*chunkedBodyBytes("\r\n"), 2u);
}

}  // namespace
}  // namespace fsdb
