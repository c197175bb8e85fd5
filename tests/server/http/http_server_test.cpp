// HttpServer's stop/listen handshake (server/http/http_server.h): a stop asked for before listen()
// runs is not lost (httplib's own stop() does nothing until it listens; `fsdb serve` stopped by a
// SIGTERM right after its port line served on until killed).
#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <thread>

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

}  // namespace
