// server/cli/log_sink.h: lines buffered in order, written on flush, when the buffer is full and at
// destruction; warnings written at once under flush_on.
#include "server/cli/log_sink.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <memory>
#include <string>

namespace fsdb {
namespace {

// A pipe whose read end is drained without blocking.
class Pipe {
 public:
  Pipe() {
    EXPECT_EQ(pipe(fds_), 0);
    EXPECT_EQ(fcntl(fds_[0], F_SETFL, O_NONBLOCK), 0);
  }
  ~Pipe() {
    close(fds_[0]);
    close(fds_[1]);
  }
  int writeEnd() const { return fds_[1]; }
  std::string drain() {
    std::string out;
    char buffer[4096];
    ssize_t n;
    while ((n = read(fds_[0], buffer, sizeof buffer)) > 0) out.append(buffer, static_cast<size_t>(n));
    return out;
  }

 private:
  int fds_[2];
};

std::shared_ptr<spdlog::logger> loggerOn(const std::shared_ptr<BufferedFdSink>& sink) {
  auto logger = std::make_shared<spdlog::logger>("test", sink);
  logger->set_pattern("%l %v");
  logger->flush_on(spdlog::level::warn);
  return logger;
}

TEST(BufferedFdSink, HoldsLinesUntilAFlushAndKeepsTheirOrder) {
  Pipe pipe;
  auto sink = std::make_shared<BufferedFdSink>(pipe.writeEnd());
  auto logger = loggerOn(sink);
  logger->info("GET /parts/{} 200", 1);
  logger->info("GET /parts/{} 404", 2);
  EXPECT_EQ(pipe.drain(), "");  // buffered
  logger->flush();
  EXPECT_EQ(pipe.drain(), "info GET /parts/1 200\ninfo GET /parts/2 404\n");
  logger->info("after");
  logger->warn("disk nearly full");  // flush_on(warn): this line and those before it, at once
  EXPECT_EQ(pipe.drain(), "info after\nwarning disk nearly full\n");
}

TEST(BufferedFdSink, WritesWhenFullAndWhenDestroyed) {
  Pipe pipe;
  auto sink = std::make_shared<BufferedFdSink>(pipe.writeEnd(), 64);
  auto logger = loggerOn(sink);
  logger->info("{}", std::string(40, 'a'));
  EXPECT_EQ(pipe.drain(), "");
  logger->info("{}", std::string(40, 'b'));  // past 64 bytes: written
  EXPECT_EQ(pipe.drain(), "info " + std::string(40, 'a') + "\ninfo " + std::string(40, 'b') + "\n");
  logger->info("last");
  logger.reset();
  sink.reset();  // the destructor writes what is left
  EXPECT_EQ(pipe.drain(), "info last\n");
}

TEST(BufferedFdSink, AClosedDescriptorDropsLinesWithoutThrowing) {
  auto sink = std::make_shared<BufferedFdSink>(-1);
  auto logger = loggerOn(sink);
  logger->info("nowhere");
  EXPECT_NO_THROW(logger->flush());
}

}  // namespace
}  // namespace fsdb
