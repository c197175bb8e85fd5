#pragma once
// brief: The server's front: one thread that accepts connections and reads each request's head,
// and its body up to the first MiB, under a deadline, before a worker takes the request. A
// connection that is idle or sends slowly holds a buffer and a file descriptor, never a worker.
// note: cpp-httplib still parses and answers every request, on a worker, through a FrontStream
// that serves the bytes the front read first and then reads the socket (the rest of a large
// body, under a minimum rate). Between the requests of a keep-alive connection the connection
// goes back to the front. Before it, a fixed pool of workers read requests themselves, so 16
// clients sending their headers a byte a second held 16 workers and /health went unanswered;
// a thread per connection instead fixed that but grew the soak's memory past its bound
// (docs/design/connection-front.md).
//
// Deadlines (FrontOptions):
// - a connection with no byte of a next request for idleTimeoutMs is closed;
// - from its first byte, a request's head and its body up to bodyPrefetchBytes must arrive within
//   readTimeoutMs plus the prefetched bytes at minBodyBytesPerSecond, else 408 and the connection
//   closes; a head past maxHeadBytes is 431;
// - a body beyond the prefetch, read by the worker, must keep up minBodyBytesPerSecond on average
//   (after a grace of readTimeoutMs), else the request fails and the connection closes;
// - past maxConnections, a new connection closes the one that has waited longest in the front.
// throws: the constructor throws std::runtime_error when epoll or eventfd cannot be created.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "server/http/request_head.h"

namespace httplib {
class Stream;
class TaskQueue;
}  // namespace httplib

namespace fsdb {

struct FrontOptions {
  int readTimeoutMs = 10000;              // a request's head and prefetched body, from its first byte
  int idleTimeoutMs = 5000;               // a keep-alive connection waiting for its next request
  int ioTimeoutMs = 5000;                 // a worker's wait for one read or one write
  size_t maxHeadBytes = 64u << 10;        // 431 beyond
  size_t bodyPrefetchBytes = 1u << 20;    // body bytes the front reads before a worker takes over
  size_t minBodyBytesPerSecond = 64u << 10;
  size_t maxConnections = 0;              // 0: from the process's file descriptor limit
  int maxRequestsPerConnection = 100;     // then "Connection: close"
  // Told the code of each answer the front writes itself ("request_timeout", "header_too_large"),
  // on the front's thread; may be empty.
  std::function<void(const std::string& code)> refused;
};

class ConnectionFront {
 public:
  // Answers one request read from `stream` (cpp-httplib's Server::process_request): false when the
  // connection is to close; `connectionClosed` set when the client asked to close it.
  using ServeRequest = std::function<bool(httplib::Stream& stream, bool closeConnection, bool& connectionClosed)>;
  // Whether a request that announces "Expect: 100-continue" may send its body. When it may, the
  // front answers "100 Continue" itself and reads the body like any other; when not, the request
  // goes to a worker at once, with its Expect line, and cpp-httplib's expect handler refuses it.
  using MayContinue = std::function<bool(const RequestHead&)>;

  // Serves the bound, listening socket `listenSocket` (owned from now on: closed when the front
  // stops) with `workers`, which must outlive run().
  ConnectionFront(int listenSocket, FrontOptions options, httplib::TaskQueue& workers, ServeRequest serve,
                  MayContinue mayContinue);
  ~ConnectionFront();
  ConnectionFront(const ConnectionFront&) = delete;
  ConnectionFront& operator=(const ConnectionFront&) = delete;

  // Serves until stop(). Then closes the listening socket and the connections in the front, lets
  // the requests the workers have finish (each answered with "Connection: close") and returns.
  void run();
  // Thread-safe, any number of times, before or during run() (run() then returns at once).
  void stop();

  int openConnections() const { return open_.load(); }  // in the front and with workers

  struct Connection;

 private:
  void acceptAll();
  void onReadable(Connection& c);
  // Whether c's current request has arrived as far as the front reads it; answers 100 Continue
  // or 431 on the way (closing c on 431 and returning false).
  bool requestReady(Connection& c);
  void dispatch(int fd);
  // What the client hears before its connection closes: nothing, or a final JSON answer.
  enum class FinalAnswer { kNone, kRequestTimeout, kHeaderTooLarge };
  void closeConnection(int fd, FinalAnswer answer);
  void sweepDeadlines();
  void takeReturned();
  void finish(std::unique_ptr<Connection> c, bool keep);  // on a worker, after a request
  void watch(Connection& c);

  const int listen_;
  const FrontOptions options_;
  httplib::TaskQueue& workers_;
  ServeRequest serve_;
  MayContinue mayContinue_;
  size_t maxConnections_ = 0;
  int epoll_ = -1, wake_ = -1;
  std::atomic<bool> stopping_{false};
  std::atomic<int> open_{0}, dispatched_{0};
  std::unordered_map<int, std::unique_ptr<Connection>> conns_;  // the front's, by fd; front thread only
  std::mutex returnedMutex_;
  std::vector<std::unique_ptr<Connection>> returned_;  // back from workers, for keep-alive
  std::chrono::steady_clock::time_point acceptPausedUntil_{};
};

}  // namespace fsdb
