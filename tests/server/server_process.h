#pragma once
// Test helper: runs the real `fsdb serve --port 0` as a child process, reads the port from the
// first stdout line (docs/api.md §1), and talks to it with an httplib client. The destructor kills
// and reaps the child, so a failing test never leaves a server behind. Extra arguments
// (--db, --token, limits) go after `serve --port 0`; kill9() simulates a crash, and a new
// ServerProcess with the same --db is a restart; without --db it gets a temporary database.
// TempDir gives each test its own directory. stderrFile, when given, receives the server's log
// (warnings and errors: it runs with --log-level warn); exchange() sends raw bytes and reads one
// answer, for requests an HTTP client library will not send.
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/db/temp_dir.h"
#include "tests/db/test_database.h"
#include "tests/testing/sanitizer_slowdown.h"

namespace fsdb::test {

// The db/ tests' temporary directory (removed with its contents at destruction).
using fsdb::TempDir;

class ServerProcess {
 public:
  explicit ServerProcess(std::vector<std::string> extraArgs = {}, const std::string& stderrFile = "") {
    // Without --db each server gets a database of its own (never data/fsdb.sqlite of the cwd): a
    // temporary file, or a new schema on the test cluster when the suite runs on PostgreSQL.
    if (std::find(extraArgs.begin(), extraArgs.end(), "--db") == extraArgs.end()) {
      ownDir_ = std::make_unique<TempDir>();
      extraArgs.push_back("--db");
      extraArgs.push_back(storeLocation(*ownDir_, "fsdb.sqlite"));
    }
    db_ = extraArgs[static_cast<size_t>(std::find(extraArgs.begin(), extraArgs.end(), "--db") - extraArgs.begin()) + 1];
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    const pid_t parent = getpid();
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      // A test that dies without its destructors (an abort under a sanitizer) takes its server
      // with it: an orphan would keep the test's stderr open and ctest would wait for it forever.
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(127);  // the test already died between fork and prctl
      dup2(out[1], STDOUT_FILENO);
      if (!stderrFile.empty()) {
        const int err = open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (err >= 0) dup2(err, STDERR_FILENO);
      }
      close(out[0]);
      close(out[1]);
      std::vector<std::string> args = {FSDB_BINARY, "--log-level", "warn", "serve", "--port", "0"};
      args.insert(args.end(), extraArgs.begin(), extraArgs.end());
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(out[1]);
    stdout_ = fdopen(out[0], "r");
    char line[256] = {0};
    if (!fgets(line, sizeof line, stdout_)) throw std::runtime_error("fsdb serve printed nothing");
    firstLine_ = line;
    if (!firstLine_.empty() && firstLine_.back() == '\n') firstLine_.pop_back();
    const std::string prefix = "listening on http://";
    if (firstLine_.rfind(prefix, 0) != 0) throw std::runtime_error("unexpected first line: " + firstLine_);
    const std::string hostPort = firstLine_.substr(prefix.size());
    host_ = hostPort.substr(0, hostPort.rfind(':'));
    port_ = std::stoi(hostPort.substr(hostPort.rfind(':') + 1));
  }

  ~ServerProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (stdout_) fclose(stdout_);
  }

  // Sends SIGKILL (a crash: no checkpoint, no graceful stop) and reaps the child.
  void kill9() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

  // Sends SIGTERM and returns the exit status (the server must stop gracefully); a server still
  // running after 60 s is killed and 124 returned, so a lost stop fails the test, not the ctest timeout.
  int terminate() {
    kill(pid_, SIGTERM);
    int status = 0;
    bool stopped = false;
    for (int ms = 0; ms < 60000 && !stopped; ms += 10) {
      stopped = waitpid(pid_, &status, WNOHANG) == pid_;
      if (!stopped) usleep(10000);
    }
    if (!stopped) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    pid_ = -1;
    if (!stopped) return 124;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  bool alive() const { return pid_ > 0 && ::kill(pid_, 0) == 0; }
  pid_t pid() const { return pid_; }
  int port() const { return port_; }
  const std::string& host() const { return host_; }
  const std::string& firstLine() const { return firstLine_; }

  httplib::Client client() const {
    httplib::Client c(host_, port_);
    c.set_read_timeout(static_cast<time_t>(120 * fsdb::testing::kSlowdown), 0);
    return c;
  }

  struct Reply {
    int status = 0;
    nlohmann::json json;
    std::string body;
    std::string contentType;
    std::string location;
  };

  // Requests carry "Authorization: Bearer <token>" when setToken() was given one.
  void setToken(std::string token) { token_ = std::move(token); }

  Reply get(const std::string& path) const {
    auto c = client();
    return toReply(c.Get(path.c_str(), headers()));
  }
  Reply post(const std::string& path, const std::string& body,
             const std::string& contentType = "application/json") const {
    auto c = client();
    return toReply(c.Post(path.c_str(), headers(), body, contentType.c_str()));
  }
  Reply post(const std::string& path, const nlohmann::json& body) const { return post(path, body.dump()); }
  Reply put(const std::string& path, const std::string& body) const {
    auto c = client();
    return toReply(c.Put(path.c_str(), headers(), body, "application/json"));
  }
  Reply put(const std::string& path, const nlohmann::json& body) const { return put(path, body.dump()); }
  Reply del(const std::string& path) const {
    auto c = client();
    return toReply(c.Delete(path.c_str(), headers()));
  }

  // Sends `bytes` on a new connection and returns what comes back until one whole answer (its
  // headers and Content-Length bytes of body) has arrived, the server closes, or timeoutMs passes
  // (then what arrived so far, maybe nothing). *elapsedMs, when given, gets the time it took.
  std::string exchange(const std::string& bytes, int timeoutMs, double* elapsedMs = nullptr) const {
    const auto start = std::chrono::steady_clock::now();
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) throw std::runtime_error("socket failed");
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port_));
    inet_pton(AF_INET, host_.c_str(), &addr.sin_addr);
    if (connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
      close(fd);
      throw std::runtime_error("connect failed");
    }
    for (size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;  // the server may close early: read what it answered
      sent += static_cast<size_t>(n);
    }
    std::string in;
    const auto deadline = start + std::chrono::milliseconds(timeoutMs);
    for (;;) {
      const size_t head = in.find("\r\n\r\n");
      if (head != std::string::npos) {
        size_t length = 0;
        const size_t at = in.find("Content-Length: ");
        if (at != std::string::npos && at < head) length = std::stoul(in.substr(at + 16));
        if (in.size() >= head + 4 + length) break;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) break;
      pollfd p{fd, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
      char buf[4096];
      const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
      if (n <= 0) break;
      in.append(buf, static_cast<size_t>(n));
    }
    close(fd);
    if (elapsedMs)
      *elapsedMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return in;
  }

  // The --db the server runs on (a second server on the same database takes it).
  const std::string& db() const { return db_; }

 private:
  httplib::Headers headers() const {
    httplib::Headers h;
    if (!token_.empty()) h.emplace("Authorization", "Bearer " + token_);
    return h;
  }

  static Reply toReply(const httplib::Result& r) {
    if (!r) throw std::runtime_error("request failed: " + httplib::to_string(r.error()));
    Reply out;
    out.status = r->status;
    out.body = r->body;
    out.contentType = r->get_header_value("Content-Type");
    out.location = r->get_header_value("Location");
    out.json = nlohmann::json::parse(r->body, nullptr, false);
    return out;
  }

  std::unique_ptr<TempDir> ownDir_;  // the database of a server started without --db
  std::string db_;                   // the --db it was started with
  pid_t pid_ = -1;
  FILE* stdout_ = nullptr;
  std::string firstLine_, host_, token_;
  int port_ = 0;
};

// Runs `fsdb ARGS...` to completion (stderr discarded unless keepStderr) and returns its exit
// status and stdout. Arguments are single-quoted for the shell.
struct CommandResult {
  int exitCode = -1;
  std::string out;
};
inline CommandResult runFsdb(const std::vector<std::string>& args, bool keepStderr = false) {
  std::string command = std::string("'") + FSDB_BINARY + "'";
  for (const std::string& a : args) {
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    command += " " + quoted + "'";
  }
  command += keepStderr ? " 2>&1" : " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed");
  CommandResult result;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

// The "name" of every result of a query answer ({"results":[{"name",...}]}), in order.
inline std::vector<std::string> resultNames(const nlohmann::json& answer) {
  std::vector<std::string> out;
  for (const nlohmann::json& r : answer["results"]) out.push_back(r["name"]);
  return out;
}

}  // namespace fsdb::test
