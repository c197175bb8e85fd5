#include "server/http/connection_front.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <httplib.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <thread>

#include "geometry/core/error.h"
#include "server/service/error_json.h"

namespace fsdb {

using Clock = std::chrono::steady_clock;

struct ConnectionFront::Connection {
  int fd = -1;
  std::string buf;  // received, not yet given to cpp-httplib; the current request starts at 0
  std::string remoteIp, localIp;
  int remotePort = 0, localPort = 0;
  Clock::time_point deadline;  // idle or read deadline of the current wait (front only)
  Clock::time_point waitingSince;
  bool started = false;                // a byte of the current request has arrived
  size_t searched = 0;                 // bytes searched for the head's blank line
  std::optional<RequestHead> head;     // the current request's, once complete
  bool continued = false;              // the front answered its Expect: 100-continue
  bool closeAfter = false;             // its length is unreadable: answer, then close
  int served = 0;                      // requests answered on this connection
};

namespace {

std::string addressText(const sockaddr_storage& a, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (a.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(a);
    inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(a);
    inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  return text;
}

int millisUntil(Clock::time_point t) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(ms, 0, 1 << 30));
}

// A whole small answer, best effort, on a connection about to close: a client too slow to take a
// few hundred bytes gets none.
void sendFinalAnswer(int fd, int status, const char* reason, const std::string& code, const std::string& message) {
  const std::string body = errorBody(code, message, "").dump();
  const std::string answer = "HTTP/1.1 " + std::to_string(status) + " " + reason +
                             "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
                             "\r\nConnection: close\r\n\r\n" + body;
  (void)::send(fd, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
}

// The largest number of connections the process can hold, leaving room for the database, logs
// and files: the soft descriptor limit raised to the hard one first.
size_t connectionsAllowed() {
  rlimit lim{};
  if (getrlimit(RLIMIT_NOFILE, &lim) == 0 && lim.rlim_cur < lim.rlim_max) {
    lim.rlim_cur = std::min<rlim_t>(lim.rlim_max, 1 << 16);
    setrlimit(RLIMIT_NOFILE, &lim);
    getrlimit(RLIMIT_NOFILE, &lim);
  }
  const size_t fds = lim.rlim_cur == RLIM_INFINITY ? (1u << 16) : static_cast<size_t>(lim.rlim_cur);
  return std::clamp<size_t>(fds > 128 ? fds - 128 : fds / 2, 16, 1u << 15);
}

}  // namespace

// cpp-httplib's view of one request on a connection: first the bytes the front read, then the
// socket, never past the request's end when its length is known, and never slower on average
// than FrontOptions::minBodyBytesPerSecond after a grace of readTimeoutMs.
class FrontStream : public httplib::Stream {
 public:
  FrontStream(ConnectionFront::Connection& c, const FrontOptions& o, std::optional<size_t> requestBytes)
      : c_(c), o_(o), remaining_(requestBytes), start_(Clock::now()) {}

  bool is_readable() const override { return pos_ < c_.buf.size() || waitFor(POLLIN, o_.ioTimeoutMs); }
  bool is_writable() const override { return waitFor(POLLOUT, o_.ioTimeoutMs); }

  ssize_t read(char* ptr, size_t size) override {
    if (remaining_) size = std::min(size, *remaining_);
    if (size == 0) return 0;  // the request's end: what follows is the next request's
    if (pos_ == c_.buf.size() && !fill()) return broken_ ? -1 : 0;
    const size_t n = std::min(size, c_.buf.size() - pos_);
    std::memcpy(ptr, c_.buf.data() + pos_, n);
    pos_ += n;
    if (remaining_) *remaining_ -= n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    for (;;) {
      const ssize_t n = ::send(c_.fd, ptr, size, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n >= 0) return n;
      if (errno == EINTR) continue;
      if ((errno != EAGAIN && errno != EWOULDBLOCK) || !waitFor(POLLOUT, o_.ioTimeoutMs)) {
        broken_ = true;
        return -1;
      }
    }
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = c_.remoteIp;
    port = c_.remotePort;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    ip = c_.localIp;
    port = c_.localPort;
  }
  socket_t socket() const override { return c_.fd; }

  // Whether the connection can carry a next request: no read or write failed and the request's
  // bytes were all read (a body left unread would be taken for the next request).
  bool inStep() const { return !broken_ && !eof_ && remaining_ && *remaining_ == 0; }
  // Drops the bytes cpp-httplib read; what is left (a pipelined next request) stays.
  void consume() { c_.buf.erase(0, pos_), pos_ = 0; }

 private:
  bool waitFor(short events, int timeoutMs) const {
    pollfd p{c_.fd, events, 0};
    for (;;) {
      const int r = ::poll(&p, 1, timeoutMs);
      if (r < 0 && errno == EINTR) continue;
      return r > 0;
    }
  }

  // Reads more of the socket into the buffer: false at the client's end, on an error, or when the
  // body has fallen behind its minimum rate.
  bool fill() {
    c_.buf.erase(0, pos_);
    pos_ = 0;
    for (;;) {
      const auto allowed = start_ + std::chrono::milliseconds(o_.readTimeoutMs) +
                           std::chrono::milliseconds(fromSocket_ * 1000 / std::max<size_t>(o_.minBodyBytesPerSecond, 1));
      const int wait = std::min(o_.ioTimeoutMs, millisUntil(allowed));
      if (wait <= 0 || !waitFor(POLLIN, wait)) return broken_ = true, false;
      char chunk[16384];
      const size_t want = remaining_ ? std::min(sizeof chunk, std::max<size_t>(*remaining_, 1)) : sizeof chunk;
      const ssize_t n = ::recv(c_.fd, chunk, want, MSG_DONTWAIT);
      if (n > 0) {
        c_.buf.append(chunk, static_cast<size_t>(n));
        fromSocket_ += static_cast<size_t>(n);
        return true;
      }
      if (n == 0) return eof_ = true, false;
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return broken_ = true, false;
    }
  }

  ConnectionFront::Connection& c_;
  const FrontOptions& o_;
  std::optional<size_t> remaining_;  // bytes of the request not yet read; nullopt: chunked
  Clock::time_point start_;
  size_t pos_ = 0, fromSocket_ = 0;
  bool broken_ = false, eof_ = false;
};

ConnectionFront::ConnectionFront(int listenSocket, FrontOptions options, httplib::TaskQueue& workers,
                                 ServeRequest serve, MayContinue mayContinue)
    : listen_(listenSocket),
      options_(options),
      workers_(workers),
      serve_(std::move(serve)),
      mayContinue_(std::move(mayContinue)) {
  maxConnections_ = options_.maxConnections ? options_.maxConnections : connectionsAllowed();
  epoll_ = epoll_create1(EPOLL_CLOEXEC);
  wake_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (epoll_ < 0 || wake_ < 0) throw std::runtime_error(std::string("connection front: ") + std::strerror(errno));
  fcntl(listen_, F_SETFL, fcntl(listen_, F_GETFL) | O_NONBLOCK);
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = listen_;
  epoll_ctl(epoll_, EPOLL_CTL_ADD, listen_, &ev);
  ev.data.fd = wake_;
  epoll_ctl(epoll_, EPOLL_CTL_ADD, wake_, &ev);
}

ConnectionFront::~ConnectionFront() {
  for (auto& [fd, c] : conns_) ::close(fd);
  for (auto& c : returned_) ::close(c->fd);
  if (epoll_ >= 0) ::close(epoll_);
  if (wake_ >= 0) ::close(wake_);
  ::close(listen_);
}

void ConnectionFront::stop() {
  stopping_.store(true);
  const uint64_t one = 1;
  (void)!::write(wake_, &one, sizeof one);
}

void ConnectionFront::run() {
  epoll_event events[256];
  auto nextSweep = Clock::now();
  while (!stopping_.load()) {
    const int n = epoll_wait(epoll_, events, 256, 100);
    for (int i = 0; i < n && !stopping_.load(); ++i) {
      const int fd = events[i].data.fd;
      if (fd == listen_) {
        acceptAll();
      } else if (fd == wake_) {
        uint64_t count;
        (void)!::read(wake_, &count, sizeof count);
        takeReturned();
      } else if (auto it = conns_.find(fd); it != conns_.end()) {
        onReadable(*it->second);
      }
    }
    if (Clock::now() >= nextSweep) {
      sweepDeadlines();
      nextSweep = Clock::now() + std::chrono::milliseconds(100);
    }
  }
  // Stopping: no new connections; those in the front close; those with workers close after their
  // answer (finish() sees stopping_), and run() returns when all have.
  epoll_ctl(epoll_, EPOLL_CTL_DEL, listen_, nullptr);
  ::shutdown(listen_, SHUT_RDWR);
  for (auto& [fd, c] : conns_) ::close(fd);
  open_ -= static_cast<int>(conns_.size());
  conns_.clear();
  while (dispatched_.load() > 0) {
    takeReturned();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  takeReturned();
}

void ConnectionFront::acceptAll() {
  if (Clock::now() < acceptPausedUntil_) return;
  for (;;) {
    sockaddr_storage addr{};
    socklen_t len = sizeof addr;
    const int fd = accept4(listen_, reinterpret_cast<sockaddr*>(&addr), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
      if (errno == EINTR || errno == ECONNABORTED) continue;
      if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
        // Out of descriptors: the listening socket stays readable, so wait a little rather than spin.
        acceptPausedUntil_ = Clock::now() + std::chrono::milliseconds(100);
      }
      return;
    }
    if (conns_.size() + static_cast<size_t>(dispatched_.load()) >= maxConnections_ && !conns_.empty()) {
      // Full: the connection that has waited longest in the front (an idle keep-alive, or the
      // slowest request) gives way to the new one.
      auto oldest = std::min_element(conns_.begin(), conns_.end(), [](const auto& a, const auto& b) {
        return a.second->waitingSince < b.second->waitingSince;
      });
      closeConnection(oldest->first, FinalAnswer::kNone);
    }
    int yes = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    auto c = std::make_unique<Connection>();
    c->fd = fd;
    c->remoteIp = addressText(addr, c->remotePort);
    sockaddr_storage local{};
    socklen_t localLen = sizeof local;
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&local), &localLen) == 0) c->localIp = addressText(local, c->localPort);
    ++open_;
    watch(*c);
    conns_.emplace(fd, std::move(c));
  }
}

void ConnectionFront::watch(Connection& c) {
  const auto now = Clock::now();
  c.waitingSince = now;
  c.deadline = now + std::chrono::milliseconds(options_.idleTimeoutMs);
  c.started = !c.buf.empty();
  if (c.started) c.deadline = now + std::chrono::milliseconds(options_.readTimeoutMs);
  epoll_event ev{};
  ev.events = EPOLLIN | EPOLLRDHUP;
  ev.data.fd = c.fd;
  epoll_ctl(epoll_, EPOLL_CTL_ADD, c.fd, &ev);
}

void ConnectionFront::onReadable(Connection& c) {
  const int fd = c.fd;
  // Read what has come, up to what the front holds for one request.
  const size_t cap = options_.maxHeadBytes + options_.bodyPrefetchBytes + 16384;
  bool peerClosed = false;
  while (c.buf.size() < cap) {
    char chunk[16384];
    const ssize_t n = ::recv(fd, chunk, std::min(sizeof chunk, cap - c.buf.size()), MSG_DONTWAIT);
    if (n > 0) {
      if (!c.started) {
        c.started = true;
        c.deadline = Clock::now() + std::chrono::milliseconds(options_.readTimeoutMs);
      }
      c.buf.append(chunk, static_cast<size_t>(n));
      continue;
    }
    if (n == 0) peerClosed = true;
    else if (errno == EINTR) continue;
    else if (errno != EAGAIN && errno != EWOULDBLOCK) peerClosed = true;
    break;
  }
  if (requestReady(c)) return dispatch(fd);
  if (conns_.count(fd) && peerClosed) closeConnection(fd, FinalAnswer::kNone);  // gone before a whole request
}

bool ConnectionFront::requestReady(Connection& c) {
  if (!c.head) {
    c.head = scanRequestHead(c.buf, c.searched);
    c.searched = c.buf.size();
    if (!c.head) {
      if (c.buf.size() > options_.maxHeadBytes) {
        closeConnection(c.fd, FinalAnswer::kHeaderTooLarge);
      }
      return false;
    }
    if (c.head->headBytes > options_.maxHeadBytes) {
      closeConnection(c.fd, FinalAnswer::kHeaderTooLarge);
      return false;
    }
    // The body's bytes the front waits for arrive at the minimum rate or sooner.
    const size_t expected = c.head->contentLength ? std::min(*c.head->contentLength, options_.bodyPrefetchBytes) : 0;
    c.deadline += std::chrono::milliseconds(expected * 1000 / std::max<size_t>(options_.minBodyBytesPerSecond, 1));
  }
  RequestHead& h = *c.head;
  if (h.bodyLengthInvalid) return c.closeAfter = true;  // cpp-httplib answers 400
  if (h.expectContinue && !c.continued) {
    if (!mayContinue_(h)) return true;  // refused by cpp-httplib's expect handler, body unsent
    static const char kContinue[] = "HTTP/1.1 100 Continue\r\n\r\n";
    (void)::send(c.fd, kContinue, sizeof kContinue - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
    // cpp-httplib must not answer it again.
    c.buf.erase(h.expectBegin, h.expectEnd - h.expectBegin);
    h.headBytes -= h.expectEnd - h.expectBegin;
    c.searched = h.headBytes;
    c.continued = true;
  }
  const size_t body = c.buf.size() - h.headBytes;
  if (h.chunked) return body >= options_.bodyPrefetchBytes || chunkedBodyBytes(std::string_view(c.buf).substr(h.headBytes));
  return body >= std::min(h.contentLength.value_or(0), options_.bodyPrefetchBytes);
}

void ConnectionFront::dispatch(int fd) {
  auto it = conns_.find(fd);
  std::shared_ptr<Connection> c(std::move(it->second));
  conns_.erase(it);
  epoll_ctl(epoll_, EPOLL_CTL_DEL, fd, nullptr);
  ++dispatched_;
  workers_.enqueue([this, c]() mutable {
    const RequestHead& h = *c->head;
    // A request's length: its head and Content-Length, or its head alone when it has neither a
    // length nor chunks (RFC 9112 §6.3: no body); unknown for chunked bodies.
    std::optional<size_t> bytes;
    if (!h.chunked && !h.bodyLengthInvalid) bytes = h.headBytes + h.contentLength.value_or(0);
    FrontStream stream(*c, options_, bytes);
    const bool closeNow =
        stopping_.load() || c->closeAfter || h.chunked || c->served + 1 >= options_.maxRequestsPerConnection;
    bool clientClosed = false;
    const bool ok = serve_(stream, closeNow, clientClosed);
    ++c->served;
    const bool keep = ok && !closeNow && !clientClosed && stream.inStep();
    if (keep) stream.consume();
    // The shared_ptr is the task's only owner: hand its Connection on.
    auto owned = std::make_unique<Connection>(std::move(*c));
    finish(std::move(owned), keep);
  });
}

void ConnectionFront::finish(std::unique_ptr<Connection> c, bool keep) {
  if (!keep || stopping_.load()) {
    ::shutdown(c->fd, SHUT_WR);
    ::close(c->fd);
    --open_;
  } else {
    c->head.reset();
    c->searched = 0;
    c->continued = false;
    std::lock_guard<std::mutex> lock(returnedMutex_);
    returned_.push_back(std::move(c));
  }
  --dispatched_;
  const uint64_t one = 1;
  (void)!::write(wake_, &one, sizeof one);
}

void ConnectionFront::takeReturned() {
  std::vector<std::unique_ptr<Connection>> back;
  {
    std::lock_guard<std::mutex> lock(returnedMutex_);
    back.swap(returned_);
  }
  for (auto& c : back) {
    if (stopping_.load()) {
      ::close(c->fd);
      --open_;
      continue;
    }
    const int fd = c->fd;
    Connection& ref = *c;
    conns_.emplace(fd, std::move(c));
    watch(ref);
    // A pipelined next request may be here already.
    if (requestReady(ref)) dispatch(fd);
  }
}

void ConnectionFront::sweepDeadlines() {
  const auto now = Clock::now();
  std::vector<std::pair<int, bool>> late;  // fd, whether a request had begun
  for (const auto& [fd, c] : conns_)
    if (now >= c->deadline) late.emplace_back(fd, c->started);
  for (const auto& [fd, started] : late) closeConnection(fd, started ? FinalAnswer::kRequestTimeout : FinalAnswer::kNone);
}

void ConnectionFront::closeConnection(int fd, FinalAnswer answer) {
  if (answer == FinalAnswer::kRequestTimeout) {
    if (options_.refused) options_.refused(errc::kRequestTimeout);
    sendFinalAnswer(fd, 408, "Request Timeout", errc::kRequestTimeout,
                    "the request's head and body did not arrive within " + std::to_string(options_.readTimeoutMs) +
                        " ms of its first byte (fsdb serve --read-timeout-ms)");
  } else if (answer == FinalAnswer::kHeaderTooLarge) {
    if (options_.refused) options_.refused(errc::kHeaderTooLarge);
    sendFinalAnswer(fd, 431, "Request Header Fields Too Large", errc::kHeaderTooLarge,
                    "the request's head is larger than " + std::to_string(options_.maxHeadBytes) + " bytes");
  }
  epoll_ctl(epoll_, EPOLL_CTL_DEL, fd, nullptr);
  ::close(fd);
  conns_.erase(fd);
  --open_;
}

}  // namespace fsdb
