#pragma once
// Test helper: runs the real `fsdb serve --port 0` as a child process, reads the port from the
// first stdout line (SPEC §1), and talks to it with an httplib client. The destructor sends
// SIGTERM and reaps the child, so a failing test never leaves a server behind.
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace fsdb::test {

class ServerProcess {
 public:
  explicit ServerProcess(std::vector<std::string> extraArgs = {}) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
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

  // Sends SIGTERM and returns the exit status (the server must stop gracefully).
  int terminate() {
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  bool alive() const { return pid_ > 0 && ::kill(pid_, 0) == 0; }
  int port() const { return port_; }
  const std::string& host() const { return host_; }
  const std::string& firstLine() const { return firstLine_; }

  httplib::Client client() const {
    httplib::Client c(host_, port_);
    c.set_read_timeout(120, 0);
    return c;
  }

  struct Reply {
    int status = 0;
    nlohmann::json json;
    std::string body;
  };

  Reply get(const std::string& path) const {
    auto c = client();
    return toReply(c.Get(path.c_str()));
  }
  Reply post(const std::string& path, const std::string& body) const {
    auto c = client();
    return toReply(c.Post(path.c_str(), body, "application/json"));
  }
  Reply post(const std::string& path, const nlohmann::json& body) const { return post(path, body.dump()); }

 private:
  static Reply toReply(const httplib::Result& r) {
    if (!r) throw std::runtime_error("request failed: " + httplib::to_string(r.error()));
    Reply out;
    out.status = r->status;
    out.body = r->body;
    out.json = nlohmann::json::parse(r->body, nullptr, false);
    return out;
  }

  pid_t pid_ = -1;
  FILE* stdout_ = nullptr;
  std::string firstLine_, host_;
  int port_ = 0;
};

}  // namespace fsdb::test
