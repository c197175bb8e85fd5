// The real `fsdb serve`: first line, /health, /openapi.json, error bodies for every kind of bad
// request, and a graceful stop on SIGTERM.
#include <gtest/gtest.h>

#include <fcntl.h>

#include <atomic>
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
  expectErrorBody(server.post("/operators/evaluate", std::string("[[[[[[[[[[[[1]]]]]]]]]]]]")), 413,
                  "limit_exceeded", "body");
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
