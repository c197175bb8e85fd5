#pragma once
// Metrics: what GET /metrics serves, in the Prometheus text format (version 0.0.4), for operators
// who tune the server's limits (docs/api.md §4 lists every metric).
//
// Contract:
// - observe(method, route, status, seconds, code) counts one answered request under its route's
//   template ("/parts/{id}", not the id: a bounded set of series), "page" for the studio page's
//   files and "none" for paths no route has; adds its latency to the route's histogram; and, with
//   a non-empty error code, counts its refusal as reject does, in the same step (a reader of
//   text() never sees the request without its refusal).
// - reject(code) counts a request refused with an error code that says the server or a limit
//   refused it (unauthorized, limit_exceeded, overloaded, method_not_allowed, storage_error, ...).
// - text(gauges) writes every counter and histogram, then the gauges given (name, help, value)
//   read at that moment by the caller (evaluations running, memory reserved, cache, pool).
// Thread-safe; a mutex (the requests it counts take milliseconds, a count takes nanoseconds).
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

namespace fsdb {

struct MetricGauge {
  std::string name, help;
  double value = 0;
  std::string type = "gauge";  // or "counter" (a total read from elsewhere)
};

class Metrics {
 public:
  // Upper bounds of the latency histogram's buckets, in seconds (+Inf follows).
  static const std::vector<double>& latencyBuckets();

  void observe(const std::string& method, const std::string& route, int status, double seconds,
               const std::string& code = "");
  void reject(const std::string& code);
  std::string text(const std::vector<MetricGauge>& gauges) const;

 private:
  struct Histogram {
    std::vector<std::uint64_t> counts;  // per bucket, not cumulative
    std::uint64_t count = 0;
    double sum = 0;
  };
  mutable std::mutex mutex_;
  std::map<std::tuple<std::string, std::string, int>, std::uint64_t> requests_;  // method, route, status
  std::map<std::pair<std::string, std::string>, Histogram> latency_;              // method, route
  std::map<std::string, std::uint64_t> rejected_;                                 // by error code
};

}  // namespace fsdb
