#pragma once
// TempDir: a fresh, uniquely named directory under the system temp directory, removed (with
// everything in it) on destruction. Shared by the tests of db/, which need real files: the store
// refuses ":memory:" (each pooled connection would get its own database).
#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace fsdb {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = std::filesystem::temp_directory_path() /
            ("fsdb_db_test_" + std::to_string(::getpid()) + "_" + std::to_string(ticks) + "_" +
             std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // A path inside the directory (not created).
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace fsdb
