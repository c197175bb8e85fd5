#pragma once
// SingleFlight<T>: work asked for under one key by several callers at the same moment runs once;
// the callers that arrive while it runs wait for it and get its result (or its exception). The
// key is forgotten when the work ends, so nothing is kept beyond the callers that waited (results
// that should last belong in a cache). Used for grid builds of one shape at one resolution
// (evaluation.cpp) and for the cached exports and thumbnails (server/http/evaluation_api.cpp).
//
// Contract: run(key, work) returns work()'s value, computed by this call or by the call with the
// same key already running; an exception of that work is rethrown to every waiting caller.
// Thread-safe. T is copied to each caller.
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <string>

namespace fsdb {

template <class T>
class SingleFlight {
 public:
  T run(const std::string& key, const std::function<T()>& work) {
    std::shared_future<T> running;
    std::promise<T> mine;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = flights_.find(key);
      if (it != flights_.end())
        running = it->second;
      else
        flights_.emplace(key, mine.get_future().share());
    }
    if (running.valid()) return running.get();  // rethrows the first caller's exception
    try {
      T value = work();
      mine.set_value(value);
      finish(key);
      return value;
    } catch (...) {
      mine.set_exception(std::current_exception());
      finish(key);
      throw;
    }
  }

 private:
  void finish(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    flights_.erase(key);
  }
  std::mutex mutex_;
  std::map<std::string, std::shared_future<T>> flights_;
};

}  // namespace fsdb
