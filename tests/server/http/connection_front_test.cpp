// The connection front (server/http/connection_front.h) against the real `fsdb serve`: slow and
// idle connections hold no worker, requests that arrive too slowly get 408, oversized heads 431,
// and whole requests (pipelined, chunked, large, announced with Expect) are served as before.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <gtest/gtest.h>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/server_process.h"

namespace {

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using Clock = std::chrono::steady_clock;

// One client connection, raw bytes both ways.
class RawConnection {
 public:
  explicit RawConnection(const ServerProcess& server) {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(server.port()));
    inet_pton(AF_INET, server.host().c_str(), &addr.sin_addr);
    connected_ = fd_ >= 0 && connect(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
  }
  ~RawConnection() {
    if (fd_ >= 0) close(fd_);
  }
  bool connected() const { return connected_; }
  bool send(const std::string& bytes) {
    for (size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return false;
      sent += static_cast<size_t>(n);
    }
    return true;
  }
  // Everything that arrives until the server closes or timeoutMs passes; *closed says which.
  std::string readAll(int timeoutMs, bool* closed = nullptr) {
    std::string in;
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      pollfd p{fd_, POLLIN, 0};
      if (left <= 0 || poll(&p, 1, static_cast<int>(left)) <= 0) break;
      char buf[65536];
      const ssize_t n = recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        if (closed) *closed = true;
        return in;
      }
      in.append(buf, static_cast<size_t>(n));
    }
    if (closed) *closed = false;
    return in;
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
};

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// 40 connections that send half a request head, and 40 that send a whole head and then none of
// its body, to a server of 4 workers: /health is answered at once every time. (When workers
// read requests themselves, every worker waited on a slow client and /health went unanswered.)
TEST(ConnectionFront, SlowConnectionsDoNotTakeTheWorkersOthersNeed) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("slow.sqlite"), "--threads", "4"});
  std::vector<std::unique_ptr<RawConnection>> slow;
  for (int i = 0; i < 80; ++i) {
    slow.push_back(std::make_unique<RawConnection>(server));
    ASSERT_TRUE(slow.back()->connected());
    ASSERT_TRUE(slow.back()->send(i % 2 ? "GET /health HTTP/1.1\r\nHost: t\r\nX-Slow: "
                                        : "POST /query HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                          "Content-Length: 5000\r\n\r\n{\"text\":"));
  }
  for (int i = 0; i < 10; ++i) {
    double ms = 0;
    const std::string answer = server.exchange("GET /health HTTP/1.1\r\nHost: t\r\n\r\n", 3000, &ms);
    EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << "probe " << i << " after " << ms << " ms: " << answer;
  }
  // /metrics counts them: 80 slow ones and the one asking.
  const auto metrics = server.get("/metrics");
  ASSERT_EQ(metrics.status, 200);
  const size_t at = metrics.body.find("\nfsdb_http_connections_open ");
  ASSERT_NE(at, std::string::npos) << metrics.body;
  EXPECT_GE(std::stod(metrics.body.substr(at + 28)), 81.0) << metrics.body.substr(at, 60);
}

// A request whose head or body stops arriving is answered 408 request_timeout (JSON) after
// --read-timeout-ms, and its connection closes; an idle connection that never began a request
// is closed without an answer (after the keep-alive wait, 5 s).
TEST(ConnectionFront, TooSlowRequestsGet408AndTheirConnectionCloses) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("timeout.sqlite"), "--read-timeout-ms", "400"});
  for (const std::string& partial : {std::string("GET /health HTTP/1.1\r\nHost: t\r\n"),
                                    std::string("POST /query HTTP/1.1\r\nHost: t\r\nContent-Length: 100\r\n\r\n{")}) {
    RawConnection c(server);
    ASSERT_TRUE(c.send(partial));
    const auto start = Clock::now();
    bool closed = false;
    const std::string answer = c.readAll(5000, &closed);
    EXPECT_EQ(answer.rfind("HTTP/1.1 408", 0), 0u) << answer;
    EXPECT_NE(answer.find(R"("code":"request_timeout")"), std::string::npos) << answer;
    EXPECT_NE(answer.find("--read-timeout-ms"), std::string::npos) << answer;
    EXPECT_TRUE(closed);
    EXPECT_GE(secondsSince(start), 0.3);
    EXPECT_LT(secondsSince(start), 4.0 * fsdb::testing::kSlowdown);
  }
  const auto metrics = server.get("/metrics");
  EXPECT_NE(metrics.body.find(R"(fsdb_rejected_requests_total{cause="request_timeout"} 2)"), std::string::npos)
      << metrics.body;
  RawConnection idle(server);
  bool closed = false;
  EXPECT_EQ(idle.readAll(9000, &closed), "");
  EXPECT_TRUE(closed);
}

// A body beyond what the front reads first (1 MiB) is read by the worker, which gives up when it
// falls behind 64 KiB/s after the grace of --read-timeout-ms: the worker is free again soon.
TEST(ConnectionFront, ABodyThatStallsPastThePrefetchFreesItsWorker) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("stall.sqlite"), "--read-timeout-ms", "400", "--threads", "2"});
  std::vector<std::unique_ptr<RawConnection>> stalled;
  const auto start = Clock::now();
  for (int i = 0; i < 2; ++i) {
    stalled.push_back(std::make_unique<RawConnection>(server));
    ASSERT_TRUE(stalled.back()->send("POST /query HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                     "Content-Length: 4000000\r\n\r\n{\"text\":\"" +
                                     std::string(1200000, 'a')));
  }
  for (auto& c : stalled) {
    bool closed = false;
    c->readAll(8000, &closed);
    EXPECT_TRUE(closed);
  }
  EXPECT_LT(secondsSince(start), 6.0 * fsdb::testing::kSlowdown);
  EXPECT_EQ(server.get("/health").status, 200);
}

// A head past 64 KiB is 431 header_too_large.
TEST(ConnectionFront, AnOversizedHeadIs431) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("big.sqlite")});
  RawConnection c(server);
  c.send("GET /health HTTP/1.1\r\nHost: t\r\n");
  for (int i = 0; i < 80; ++i)
    if (!c.send("X-Pad-" + std::to_string(i) + ": " + std::string(1000, 'p') + "\r\n")) break;
  bool closed = false;
  const std::string answer = c.readAll(5000, &closed);
  EXPECT_EQ(answer.rfind("HTTP/1.1 431", 0), 0u) << answer.substr(0, 200);
  EXPECT_NE(answer.find(R"("code":"header_too_large")"), std::string::npos) << answer.substr(0, 300);
  EXPECT_TRUE(closed);
}

// Requests sent back to back on one connection are answered in order; the last asks to close.
TEST(ConnectionFront, PipelinedRequestsAreAnsweredInOrder) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("pipe.sqlite")});
  RawConnection c(server);
  const std::string query = R"({"text":"a sphere"})";
  ASSERT_TRUE(c.send("GET /health HTTP/1.1\r\nHost: t\r\n\r\n"
                     "POST /query HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nContent-Length: " +
                     std::to_string(query.size()) + "\r\n\r\n" + query +
                     "GET /nothing-here HTTP/1.1\r\nHost: t\r\n\r\n"
                     "GET /health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n"));
  bool closed = false;
  const std::string answers = c.readAll(5000, &closed);
  EXPECT_TRUE(closed);
  ASSERT_EQ(count(answers, "HTTP/1.1 "), 4u) << answers;
  const size_t first = answers.find("HTTP/1.1 200"), second = answers.find("HTTP/1.1 200", first + 1),
               third = answers.find("HTTP/1.1 404"), fourth = answers.rfind("HTTP/1.1 200");
  EXPECT_LT(first, second);
  EXPECT_LT(second, third);
  EXPECT_LT(third, fourth);
  EXPECT_NE(answers.find(R"("candidates")"), std::string::npos) << answers;
}

// A POST with neither Content-Length nor chunks has no body (RFC 9112 §6.3): it is answered at
// once (cpp-httplib, reading on its own, waited 5 s for the connection to close), and the
// connection serves the next request.
TEST(ConnectionFront, ARequestWithoutALengthHasNoBody) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("nolength.sqlite")});
  RawConnection c(server);
  const auto start = Clock::now();
  ASSERT_TRUE(c.send("POST /query HTTP/1.1\r\nHost: t\r\n\r\nGET /health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n"));
  const std::string answers = c.readAll(5000);
  EXPECT_LT(secondsSince(start), 2.0 * fsdb::testing::kSlowdown);
  EXPECT_EQ(answers.rfind("HTTP/1.1 400", 0), 0u) << answers;
  EXPECT_NE(answers.find(R"("code":"malformed_json")"), std::string::npos) << answers;
  EXPECT_NE(answers.find("HTTP/1.1 200"), std::string::npos) << answers;
}

// Bodies past what the front reads first, chunked bodies, and bodies announced with
// "Expect: 100-continue" (the front answers 100 itself when the write is allowed) all arrive whole.
TEST(ConnectionFront, LargeChunkedAndContinuedBodiesArriveWhole) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("bodies.sqlite"), "--token", "s3cret"});
  // 3 MB: a query padded with spaces, which JSON ignores.
  const std::string large = R"({"text":"a sphere")" + std::string(3000000, ' ') + "}";
  const auto big = server.post("/query", large);
  EXPECT_EQ(big.status, 200) << big.body.substr(0, 300);

  RawConnection chunked(server);
  const std::string half1 = R"({"text":)", half2 = R"("a cylinder"})";
  auto hex = [](size_t n) {
    char b[32];
    snprintf(b, sizeof b, "%zx", n);
    return std::string(b);
  };
  ASSERT_TRUE(chunked.send("POST /query HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                           "Transfer-Encoding: chunked\r\n\r\n" +
                           hex(half1.size()) + "\r\n" + half1 + "\r\n" + hex(half2.size()) + ";ext=1\r\n" + half2 +
                           "\r\n0\r\n\r\n"));
  const std::string chunkedAnswer = chunked.readAll(5000);
  EXPECT_EQ(chunkedAnswer.rfind("HTTP/1.1 200", 0), 0u) << chunkedAnswer;

  const std::string part = R"({"kind":"part","name":"continued","params":{"a1":1}})";
  RawConnection continued(server);
  ASSERT_TRUE(continued.send("POST /parts HTTP/1.1\r\nHost: t\r\nAuthorization: Bearer s3cret\r\n"
                             "Content-Type: application/json\r\nExpect: 100-continue\r\nContent-Length: " +
                             std::to_string(part.size()) + "\r\n\r\n"));
  std::string got = continued.readAll(1000);
  ASSERT_EQ(got, "HTTP/1.1 100 Continue\r\n\r\n");
  ASSERT_TRUE(continued.send(part));
  got = continued.readAll(3000);
  EXPECT_EQ(got.rfind("HTTP/1.1 201", 0), 0u) << got;
  EXPECT_EQ(count(got, "100 Continue"), 0u) << got;
}

}  // namespace
