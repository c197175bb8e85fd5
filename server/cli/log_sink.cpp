// See server/cli/log_sink.h.
#include "server/cli/log_sink.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <pthread.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>

namespace fsdb {

BufferedFdSink::~BufferedFdSink() {
  std::lock_guard<std::mutex> lock(mutex_);
  writeBuffer();
}

void BufferedFdSink::sink_it_(const spdlog::details::log_msg& msg) {
  spdlog::memory_buf_t line;
  formatter_->format(msg, line);
  buffer_.append(line.data(), line.size());
  if (buffer_.size() >= kFlushBytes) writeBuffer();
}

void BufferedFdSink::flush_() { writeBuffer(); }

void BufferedFdSink::writeBuffer() {
  size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // a closed or full stderr: the log is dropped, never the server
    done += static_cast<size_t>(n);
  }
  buffer_.clear();
}

void installLogger() {
  std::shared_ptr<spdlog::logger> logger;
  if (::isatty(STDERR_FILENO)) {
    logger = spdlog::stderr_color_mt("fsdb");
  } else {
    logger = std::make_shared<spdlog::logger>("fsdb", std::make_shared<BufferedFdSink>(STDERR_FILENO));
    logger->flush_on(spdlog::level::warn);
    // The flushing thread starts with every signal blocked: a thread inherits its creator's mask,
    // and one that left SIGTERM open would take `fsdb serve`'s SIGTERM with the default action
    // (death, exit 143) before the server's own waiter could stop it cleanly.
    sigset_t all, previous;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &previous);
    spdlog::flush_every(kLogFlushInterval);  // flushes every registered logger; the default is one
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  }
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");
}

}  // namespace fsdb
