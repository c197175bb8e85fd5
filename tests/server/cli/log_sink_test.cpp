// BufferedFdSink (server/cli/log_sink.h): lines reach the descriptor in order, when the buffer
// is full, when flushed (at once for warn with flush_on, as installLogger sets it) and when the
// sink goes; nothing is written per line before that.
#include "server/cli/log_sink.h"

#include <fcntl.h>
#include <csignal>
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <memory>
#include <string>

namespace fsdb {
namespace {

// A pipe whose read end never blocks: read() gives what has been written so far.
class Pipe {
 public:
  Pipe() {
    EXPECT_EQ(::pipe(fds_), 0);
    ::fcntl(fds_[0], F_SETFL, O_NONBLOCK);
    ::fcntl(fds_[1], F_SETPIPE_SZ, 1 << 20);  // room for the test's lines without a reader
  }
  ~Pipe() {
    ::close(fds_[0]);
    ::close(fds_[1]);
  }
  int writeEnd() const { return fds_[1]; }
  std::string read() {
    std::string out;
    char bytes[65536];
    ssize_t n;
    while ((n = ::read(fds_[0], bytes, sizeof bytes)) > 0) out.append(bytes, static_cast<size_t>(n));
    return out;
  }

 private:
  int fds_[2];
};

std::shared_ptr<spdlog::logger> loggerOn(int fd) {
  auto logger = std::make_shared<spdlog::logger>("test", std::make_shared<BufferedFdSink>(fd));
  logger->set_pattern("%l %v");
  logger->flush_on(spdlog::level::warn);
  return logger;
}

TEST(BufferedFdSink, WritesNothingPerLineUntilFlushed) {
  Pipe pipe;
  auto logger = loggerOn(pipe.writeEnd());
  logger->info("GET /parts/1 200");
  logger->info("GET /parts/2 200");
  EXPECT_EQ(pipe.read(), "");
  logger->flush();
  EXPECT_EQ(pipe.read(), "info GET /parts/1 200\ninfo GET /parts/2 200\n");
  EXPECT_EQ(pipe.read(), "");
}

TEST(BufferedFdSink, AWarningWritesItAndEverythingBeforeItInOrder) {
  Pipe pipe;
  auto logger = loggerOn(pipe.writeEnd());
  logger->info("first");
  logger->warn("second");
  EXPECT_EQ(pipe.read(), "info first\nwarning second\n");
  logger->error("third");
  EXPECT_EQ(pipe.read(), "error third\n");
}

TEST(BufferedFdSink, AFullBufferIsWrittenWithoutAFlush) {
  Pipe pipe;
  auto logger = loggerOn(pipe.writeEnd());
  const std::string line(100, 'x');
  size_t logged = 0;
  while (logged < BufferedFdSink::kFlushBytes) {
    logger->info(line);
    logged += line.size() + 6;  // "info " and the newline
  }
  const std::string written = pipe.read();
  EXPECT_GE(written.size(), BufferedFdSink::kFlushBytes);
  EXPECT_EQ(written.size() % (line.size() + 6), 0u);  // whole lines only
}

TEST(BufferedFdSink, WhatIsBufferedIsWrittenWhenTheSinkGoes) {
  Pipe pipe;
  {
    auto logger = loggerOn(pipe.writeEnd());
    logger->info("last words");
    EXPECT_EQ(pipe.read(), "");
  }
  EXPECT_EQ(pipe.read(), "info last words\n");
}

TEST(BufferedFdSink, AClosedDescriptorLosesTheLinesNotTheProcess) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ::close(fds[0]);  // writes now fail with EPIPE (SIGPIPE is ignored below)
  auto previous = ::signal(SIGPIPE, SIG_IGN);
  {
    auto logger = loggerOn(fds[1]);
    logger->info("nobody reads this");
    logger->warn("nor this");
  }
  ::signal(SIGPIPE, previous);
  ::close(fds[1]);
  SUCCEED();
}

}  // namespace
}  // namespace fsdb
