// A PostgreSQL outage under a running `fsdb serve`: every request gets 503 storage_error, and the
// server's log says why in a warning line that names the cause (before, only the clients saw it),
// one line a second at most however many requests fail. The suite starts a cluster of its own
// (scripts/pg-test-cluster) so that it can stop it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

std::string cluster(const std::string& action, const std::string& dir) {
  const std::string command =
      std::string(FSDB_SOURCE_DIR) + "/scripts/pg-test-cluster " + action + " '" + dir + "' >/dev/null 2>&1";
  if (std::system(command.c_str()) != 0) return "";
  std::ifstream url(dir + "/url");
  std::string line;
  std::getline(url, line);
  return action == "start" ? line : "stopped";
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(StorageOutage, ClientsGet503AndTheLogNamesTheCauseOnceASecond) {
  TempDir dir;
  const std::string clusterDir = dir.file("pg");
  const std::string url = cluster("start", clusterDir);
  if (url.empty()) {
    if (std::getenv("CI")) FAIL() << "scripts/pg-test-cluster could not start a cluster";
    GTEST_SKIP() << "no PostgreSQL here (scripts/install-deps installs it)";
  }
  const std::string log = dir.file("serve.log");
  {
    ServerProcess server({"--db", url}, log);
    ASSERT_EQ(server.post("/parts", json{{"name", "before"}, {"params", {{"a1", 1}}}}).status, 201);
    ASSERT_EQ(cluster("stop", clusterDir), "stopped");
    std::string message;
    for (int i = 0; i < 5; ++i) {
      auto r = server.get("/parts");
      EXPECT_EQ(r.status, 503) << r.body;
      EXPECT_EQ(r.json["error"]["code"], "storage_error") << r.body;
      message = r.json["error"]["message"].get<std::string>();
    }
    const std::string text = fileText(log);
    EXPECT_EQ(count(text, "database failure (503)"), 1u) << text;
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    auto r = server.get("/parts");
    EXPECT_EQ(r.status, 503);
    // The cause the client was told is in the log too, in the same words ("cannot connect to
    // ...: Connection refused"; the first line has what the pooled connection saw).
    message = r.json["error"]["message"].get<std::string>();
    const std::string later = fileText(log);
    EXPECT_EQ(count(later, "database failure (503)"), 2u) << later;
    EXPECT_NE(later.find("4 more failures in the last second"), std::string::npos) << later;
    EXPECT_NE(later.find(message), std::string::npos) << "log: " << later << "\nmessage: " << message;
  }
}

}  // namespace
