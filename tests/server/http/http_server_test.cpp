// HttpServer's stop/listen handshake (server/http/http_server.h): a stop asked for before listen()
// runs is not lost (httplib's own stop() does nothing until it listens; `fsdb serve` stopped by a
// SIGTERM right after its port line served on until killed).
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <future>
#include <thread>
#include <vector>

#include "server/http/http_server.h"

namespace {

using namespace std::chrono_literals;

fsdb::ServerOptions anyPort() {
  fsdb::ServerOptions options;
  options.port = 0;  // a free one
  return options;
}

TEST(HttpServer, StopBeforeListenMakesListenReturnAtOnce) {
  fsdb::HttpServer server(anyPort());
  server.bind();
  std::thread stopper([&server]() { server.stop(); });
  std::this_thread::sleep_for(100ms);  // the stop surely comes first
  auto listening = std::async(std::launch::async, [&server]() { server.listen(); });
  const bool returned = listening.wait_for(10s) == std::future_status::ready;
  EXPECT_TRUE(returned) << "listen() served on after stop()";
  if (!returned) server.stop();  // now running: this one ends it
  listening.wait();
  stopper.join();
}

TEST(HttpServer, StopWhileListeningMakesListenReturn) {
  fsdb::HttpServer server(anyPort());
  server.bind();
  auto listening = std::async(std::launch::async, [&server]() { server.listen(); });
  std::this_thread::sleep_for(100ms);
  server.stop();
  EXPECT_EQ(listening.wait_for(10s), std::future_status::ready);
  listening.wait();
}

// While nobody accepts (bind() done, listen() not yet running), the kernel completes handshakes
// into the accept queue up to its backlog: with httplib's 5, six of 64 connects complete and the
// rest wait for SYN retries (1 s and more); fsdb asks for the kernel's largest queue.
TEST(HttpServer, ListensWithABacklogForManyClientsAtOnce) {
  fsdb::HttpServer server(anyPort());
  const int port = server.bind();
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  constexpr int kClients = 64;
  std::vector<pollfd> fds;
  for (int i = 0; i < kClients; ++i) {
    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    ASSERT_GE(fd, 0);
    connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr);  // EINPROGRESS
    fds.push_back({fd, POLLOUT, 0});
  }
  int connected = 0;
  const auto deadline = std::chrono::steady_clock::now() + 500ms;
  while (connected < kClients && std::chrono::steady_clock::now() < deadline) {
    poll(fds.data(), fds.size(), 50);
    connected = 0;
    for (pollfd& p : fds) {
      int error = 0;
      socklen_t length = sizeof error;
      if ((p.revents & POLLOUT) && getsockopt(p.fd, SOL_SOCKET, SO_ERROR, &error, &length) == 0 && error == 0)
        ++connected;
    }
  }
  EXPECT_EQ(connected, kClients);
  for (pollfd& p : fds) close(p.fd);
  auto listening = std::async(std::launch::async, [&server]() { server.listen(); });
  server.stop();
  listening.wait();
}

}  // namespace
