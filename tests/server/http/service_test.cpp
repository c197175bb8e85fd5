// The real `fsdb serve`: first line, /health, /openapi.json, error bodies for every kind of bad
// request, and a graceful stop on SIGTERM.
#include <gtest/gtest.h>

#include <fcntl.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;

namespace {

void expectErrorBody(const ServerProcess::Reply& r, int status, const std::string& code, const std::string& path) {
  EXPECT_EQ(r.status, status) << r.body;
  ASSERT_TRUE(r.json.is_object()) << r.body;
  ASSERT_TRUE(r.json.contains("error")) << r.body;
  EXPECT_EQ(r.json["error"]["code"], code) << r.body;
  EXPECT_EQ(r.json["error"]["path"], path) << r.body;
  EXPECT_FALSE(r.json["error"]["message"].get<std::string>().empty());
}

TEST(Service, FirstLineNamesTheBoundAddress) {
  ServerProcess server;
  EXPECT_EQ(server.firstLine(), "listening on http://127.0.0.1:" + std::to_string(server.port()));
  EXPECT_GT(server.port(), 0);
}

TEST(Service, HealthReportsStatusAndVersion) {
  ServerProcess server;
  auto r = server.get("/health");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.json["status"], "ok");
  EXPECT_TRUE(r.json["version"].is_string());
}

TEST(Service, ServesItsOpenApiDocument) {
  ServerProcess server;
  auto r = server.get("/openapi.json");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.json["openapi"].get<std::string>().substr(0, 2), "3.");
  EXPECT_TRUE(r.json["paths"].contains("/operators/evaluate"));
}

TEST(Service, BadRequestsGetJsonErrorsAndTheServerKeepsServing) {
  ServerProcess server({"--max-body-bytes", "1000", "--max-json-depth", "8"});
  expectErrorBody(server.get("/no/such/thing"), 404, "not_found", "");
  expectErrorBody(server.get("/operators/evaluate"), 405, "method_not_allowed", "");
  expectErrorBody(server.post("/operators/evaluate", std::string("{not json")), 400, "malformed_json", "body");
  expectErrorBody(server.post("/operators/evaluate", std::string("")), 400, "malformed_json", "body");
  expectErrorBody(server.post("/operators/evaluate", std::string(2000, ' ') + "{}"), 413, "limit_exceeded", "body");
  expectErrorBody(server.post("/operators/evaluate", std::string("[[[[[[[[[[[[1]]]]]]]]]]]]")), 413, "limit_exceeded",
                  "body");
  expectErrorBody(server.post("/operators/evaluate", std::string("[1,2]")), 422, "invalid_document", "");
  EXPECT_EQ(server.get("/health").status, 200);
}

TEST(Service, ConcurrentClientsAreAllServed) {
  ServerProcess server({"--threads", "4"});
  std::vector<std::thread> clients;
  std::atomic<int> ok{0};
  for (int t = 0; t < 8; ++t)
    clients.emplace_back([&] {
      for (int i = 0; i < 25; ++i)
        if (server.get("/health").status == 200) ++ok;
    });
  for (auto& c : clients) c.join();
  EXPECT_EQ(ok.load(), 200);
}

TEST(Service, StopsGracefullyOnSigterm) {
  ServerProcess server;
  ASSERT_EQ(server.get("/health").status, 200);
  EXPECT_EQ(server.terminate(), 0);
}

// The test harness: a test process that dies without its destructors (an abort under a
// sanitizer) must not leave its server running. The orphan held the test's stderr, and ctest
// waited for it for as long as it lived (8 minutes, until it was killed by hand).
TEST(ServerProcessHarness, AServerDiesWithTheTestThatStartedIt) {
  int report[2];
  ASSERT_EQ(pipe(report), 0);
  const pid_t test = fork();
  if (test == 0) {
    close(report[0]);
    ServerProcess server;
    const pid_t serverPid = server.pid();
    if (write(report[1], &serverPid, sizeof serverPid) != sizeof serverPid) _exit(2);
    _exit(0);  // no destructors: as a sanitizer's abort
  }
  close(report[1]);
  pid_t serverPid = 0;
  ASSERT_EQ(read(report[0], &serverPid, sizeof serverPid), static_cast<ssize_t>(sizeof serverPid));
  close(report[0]);
  int status = 0;
  waitpid(test, &status, 0);
  // Gone, or a zombie waiting for init to reap it, within 10 s.
  auto running = [serverPid] {
    std::ifstream stat("/proc/" + std::to_string(serverPid) + "/stat");
    std::string pid, name, state;
    return stat >> pid >> name >> state && state != "Z";
  };
  for (int i = 0; i < 1000 && running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_FALSE(running()) << "fsdb serve " << serverPid << " outlived its test process";
  if (running()) ::kill(serverPid, SIGKILL);
}

TEST(Service, RefusesAPortInUse) {
  ServerProcess first;
  // A second server on the first one's port must fail with exit 1, not serve or hang.
  pid_t pid = fork();
  if (pid == 0) {
    int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, STDOUT_FILENO);
    dup2(devnull, STDERR_FILENO);
    std::string port = std::to_string(first.port());
    execl(FSDB_BINARY, FSDB_BINARY, "serve", "--port", port.c_str(), (char*)nullptr);
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
}

}  // namespace
