// A bulk body of bad lines cannot exhaust the server's memory: every bad line is counted, only
// the first --max-bulk-errors are listed (errors_truncated), and the body is read a document at a
// time. Before, each bad line kept ~1.9 KB of errors until the answer was sent: a 60 MB body of
// zeros (under the default 64 MiB body limit) grew the server past 11 GB.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "tests/server/server_process.h"
#include "tests/testing/sanitizer_slowdown.h"

namespace fsdb::test {
namespace {

// The server's peak resident memory so far (VmHWM), in MiB.
double peakRssMib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      status >> kb;
      std::printf("server peak RSS: %.0f MiB\n", kb / 1024.0);
      return kb / 1024.0;
    }
  }
  ADD_FAILURE() << "no VmHWM in /proc/" << pid << "/status";
  return 0;
}

// An array of `n` zeros, 2n + 1 bytes, every element a bad document.
std::string zerosArray(size_t n) {
  std::string body = "[";
  body.reserve(2 * n + 1);
  for (size_t i = 0; i < n; ++i) body += i + 1 < n ? "0," : "0]";
  return body;
}

// A 60 MB body. Under ASan + UBSan (make test-sanitize) a 6 MB one: the same path in a tenth of
// the time, the answer checked the same way, but no RSS bound (sanitizer_slowdown.h).
constexpr size_t kZeros = fsdb::testing::kSanitizerBuild ? 3000000 : 30000000;

void expectPeakRssUnder500MiB(pid_t pid) {
  const double peak = peakRssMib(pid);
  if (!fsdb::testing::kSanitizerBuild) {
    EXPECT_LT(peak, 500.0);
  }
}

TEST(BulkMemory, SixtyMegabytesOfBadArrayElementsStayUnder500MiB) {
  ServerProcess server;
  const std::string body = zerosArray(kZeros);
  ASSERT_EQ(body.size(), 2 * kZeros + 1);
  const auto r = server.post("/parts/bulk", body);
  ASSERT_EQ(r.status, 200) << r.body.substr(0, 300);
  EXPECT_EQ(r.json["imported"], 0);
  EXPECT_EQ(r.json["failed"], kZeros);
  ASSERT_EQ(r.json["errors"].size(), 1000u);
  EXPECT_EQ(r.json["errors"][0]["line"], 1);
  EXPECT_EQ(r.json["errors"][999]["line"], 1000);
  EXPECT_EQ(r.json["errors"][0]["error"]["code"], "invalid_document");
  EXPECT_EQ(r.json["errors_truncated"], true);
  EXPECT_LT(r.body.size(), 200000u);
  expectPeakRssUnder500MiB(server.pid());
  EXPECT_EQ(server.get("/health").status, 200);
}

TEST(BulkMemory, SixtyMegabytesOfBadJsonLinesStayUnder500MiB) {
  ServerProcess server({"--max-bulk-errors", "10"});
  std::string body;
  body.reserve(2 * kZeros);
  for (size_t i = 0; i < kZeros; ++i) body += i % 2 ? "[\n" : "0\n";  // a number, a malformed line
  const auto r = server.post("/parts/bulk", body, "application/x-ndjson");
  ASSERT_EQ(r.status, 200) << r.body.substr(0, 300);
  EXPECT_EQ(r.json["failed"], kZeros);
  ASSERT_EQ(r.json["errors"].size(), 10u);
  EXPECT_EQ(r.json["errors"][0]["error"]["code"], "invalid_document");
  EXPECT_EQ(r.json["errors"][1]["error"]["code"], "malformed_json");
  EXPECT_EQ(r.json["errors"][9]["line"], 10);
  EXPECT_EQ(r.json["errors_truncated"], true);
  expectPeakRssUnder500MiB(server.pid());
}

// Good lines after many bad ones are still imported, and the answer lists none when asked for none.
TEST(BulkMemory, GoodLinesAmongBadOnesAreImported) {
  ServerProcess server({"--max-bulk-errors", "0"});
  std::string body;
  for (int i = 0; i < 3000; ++i)
    body += i % 1000 == 999 ? R"({"name":"good-)" + std::to_string(i) + R"(","params":{"a1":1}})" + "\n" : "0\n";
  const auto r = server.post("/parts/bulk", body, "application/x-ndjson");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["imported"], 3);
  EXPECT_EQ(r.json["failed"], 2997);
  EXPECT_TRUE(r.json["errors"].empty());
  EXPECT_EQ(r.json["errors_truncated"], true);
  EXPECT_EQ(server.get("/parts?name=good-2999").json["items"].size(), 1u);
}

}  // namespace
}  // namespace fsdb::test
