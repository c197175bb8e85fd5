// The sink of fsdb's log lines (the request log among them).
//
// On a terminal every line is written as it is logged, in colour. Anywhere else (a file, a
// pipe, a service manager) lines are gathered and written in blocks: one write(2) per line was
// the request log's whole cost under load (docs/performance.md, Service).
#pragma once

#include <spdlog/sinks/base_sink.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <string>

namespace fsdb {

/// @brief A sink that appends formatted lines to a buffer and writes the buffer to a file
///   descriptor when it holds kFlushBytes, when flushed, and when destroyed.
/// @note Lines logged since the last write are lost if the process is killed (SIGKILL, a
///   crash); installLogger bounds that to the last kLogFlushInterval and to lines below warn.
class BufferedFdSink : public spdlog::sinks::base_sink<std::mutex> {
 public:
  static constexpr size_t kFlushBytes = 32 * 1024;

  /// @brief Writes to `fd` (not owned, never closed).
  explicit BufferedFdSink(int fd) : fd_(fd) {}
  ~BufferedFdSink() override;

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override;
  void flush_() override;

 private:
  void writeBuffer();
  int fd_;
  std::string buffer_;
};

/// How long a line below warn may wait in a BufferedFdSink before it is written.
constexpr std::chrono::seconds kLogFlushInterval{1};

/// @brief Makes the default logger "fsdb" on stderr: a colour sink when stderr is a terminal,
///   else a BufferedFdSink written at least every kLogFlushInterval and at once for warn and
///   above. Call spdlog::shutdown() before main returns (it writes what is buffered).
void installLogger();

}  // namespace fsdb
