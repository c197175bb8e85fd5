#pragma once
// The sink of fsdb's log when stderr is not a terminal (a server writing to a file or a journal).
//
// Contract
// - A line is formatted by the thread that logs it, under the sink's mutex as in every spdlog
//   sink, and appended to a buffer; the buffer goes to the file descriptor in one write(2) when
//   it holds `capacity` bytes, when spdlog flushes (fsdb flushes every second and at once for a
//   warning or an error: spdlog::flush_every, flush_on), and when the sink is destroyed
//   (spdlog::shutdown()). Lines keep their order.
// - Why: spdlog's stderr sinks write and flush every line, a system call per request under one
//   mutex; bench/bench_get_part.sh measured the request log at info costing GET /parts/{id} a
//   third of its throughput that way (docs/performance.md).
// - A failed write is retried on EINTR and otherwise drops the buffer: the log never stops the
//   server.
#include <spdlog/sinks/base_sink.h>

#include <mutex>
#include <string>

namespace fsdb {

class BufferedFdSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit BufferedFdSink(int fd, size_t capacity = 64 * 1024);
  ~BufferedFdSink() override;

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override;
  void flush_() override;

 private:
  void writeBuffer();
  int fd_;
  size_t capacity_;
  std::string buffer_;
};

}  // namespace fsdb
