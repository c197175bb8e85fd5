// contentHash: 32 hex digits, the first 16 standard FNV-1a 64 (published test vectors), stable.
#include "db/content_hash.h"

#include <gtest/gtest.h>

#include <set>

namespace fsdb {
namespace {

TEST(ContentHash, FirstHalfIsStandardFnv1a64) {
  // Test vectors of the FNV reference (isthe.com/chongo/tech/comp/fnv).
  EXPECT_EQ(contentHash("").substr(0, 16), "cbf29ce484222325");
  EXPECT_EQ(contentHash("a").substr(0, 16), "af63dc4c8601ec8c");
  EXPECT_EQ(contentHash("foobar").substr(0, 16), "85944171f73967e8");
}

TEST(ContentHash, IsStable) {
  // Pinned: stored hashes must keep matching after any rebuild.
  EXPECT_EQ(contentHash(""), "cbf29ce48422232562b821756295c58d");
  EXPECT_EQ(contentHash("{\"kind\":\"part\"}"), contentHash("{\"kind\":\"part\"}"));
  EXPECT_EQ(contentHash("abc").size(), 32u);
}

TEST(ContentHash, DifferentInputsDiffer) {
  std::set<std::string> seen;
  for (const char* text : {"", "a", "b", "ab", "ba", "{\"x\":1}", "{\"x\":2}", "{\"x\":1} "})
    seen.insert(contentHash(text));
  EXPECT_EQ(seen.size(), 8u);
}

TEST(ContentHash, SecondHalfIsOrderSensitiveIndependently) {
  // "ab" and "ba" differ in both halves: the halves are separate hashes, not one repeated.
  auto ab = contentHash("ab"), ba = contentHash("ba");
  EXPECT_NE(ab.substr(0, 16), ba.substr(0, 16));
  EXPECT_NE(ab.substr(16), ba.substr(16));
  EXPECT_NE(ab.substr(0, 16), ab.substr(16));
}

TEST(ContentHash, LowercaseHex) {
  for (char c : contentHash("any document")) EXPECT_TRUE((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'));
}

}  // namespace
}  // namespace fsdb
