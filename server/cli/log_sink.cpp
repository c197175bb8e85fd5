// See server/cli/log_sink.h.
#include "server/cli/log_sink.h"

#include <unistd.h>

#include <cerrno>

namespace fsdb {

BufferedFdSink::BufferedFdSink(int fd, size_t capacity) : fd_(fd), capacity_(capacity) {
  buffer_.reserve(capacity_ + 1024);
}

BufferedFdSink::~BufferedFdSink() {
  std::lock_guard<std::mutex> lock(mutex_);
  writeBuffer();
}

void BufferedFdSink::sink_it_(const spdlog::details::log_msg& msg) {
  spdlog::memory_buf_t formatted;
  formatter_->format(msg, formatted);
  buffer_.append(formatted.data(), formatted.size());
  if (buffer_.size() >= capacity_) writeBuffer();
}

void BufferedFdSink::flush_() { writeBuffer(); }

void BufferedFdSink::writeBuffer() {
  size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // a closed or full descriptor: the lines are dropped, the server goes on
    done += static_cast<size_t>(n);
  }
  buffer_.clear();
}

}  // namespace fsdb
