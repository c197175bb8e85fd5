// See server/http/metrics.h.
#include "server/http/metrics.h"

#include <cmath>

#include "geometry/core/number_format.h"

namespace fsdb {
namespace {

// A label value: backslash, double quote and newline escaped (the text format's rule).
std::string label(const std::string& value) {
  std::string out;
  for (char c : value) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

// The text format's numbers: formatNumber's shortest round-trip form, and its spelling of the
// infinities.
std::string number(double v) {
  if (std::isinf(v)) return v > 0 ? "+Inf" : "-Inf";
  return formatNumber(v);
}

}  // namespace

const std::vector<double>& Metrics::latencyBuckets() {
  static const std::vector<double> buckets = {0.001, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25,
                                              0.5,   1,     2.5,  5,     10,   30,  60};
  return buckets;
}

void Metrics::observe(const std::string& method, const std::string& route, int status, double seconds,
                      const std::string& code) {
  const auto& buckets = latencyBuckets();
  std::lock_guard<std::mutex> lock(mutex_);
  ++requests_[{method, route, status}];
  if (!code.empty()) ++rejected_[code];
  Histogram& h = latency_[{method, route}];
  if (h.counts.empty()) h.counts.assign(buckets.size() + 1, 0);
  size_t b = 0;
  while (b < buckets.size() && seconds > buckets[b]) ++b;
  ++h.counts[b];
  ++h.count;
  h.sum += seconds;
}

void Metrics::reject(const std::string& code) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++rejected_[code];
}

std::string Metrics::text(const std::vector<MetricGauge>& gauges) const {
  std::string out;
  const auto& buckets = latencyBuckets();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    out += "# HELP fsdb_http_requests_total Requests answered, by method, route template and status.\n";
    out += "# TYPE fsdb_http_requests_total counter\n";
    for (const auto& [key, n] : requests_)
      out += "fsdb_http_requests_total{method=\"" + label(std::get<0>(key)) + "\",route=\"" + label(std::get<1>(key)) +
             "\",status=\"" + std::to_string(std::get<2>(key)) + "\"} " + std::to_string(n) + "\n";
    out += "# HELP fsdb_http_request_duration_seconds Time from the request line to the answer, by method and route.\n";
    out += "# TYPE fsdb_http_request_duration_seconds histogram\n";
    for (const auto& [key, h] : latency_) {
      const std::string labels = "method=\"" + label(key.first) + "\",route=\"" + label(key.second) + "\"";
      std::uint64_t cumulative = 0;
      for (size_t b = 0; b <= buckets.size(); ++b) {
        cumulative += h.counts[b];
        out += "fsdb_http_request_duration_seconds_bucket{" + labels + ",le=\"" +
               (b < buckets.size() ? number(buckets[b]) : std::string("+Inf")) + "\"} " + std::to_string(cumulative) +
               "\n";
      }
      out += "fsdb_http_request_duration_seconds_sum{" + labels + "} " + number(h.sum) + "\n";
      out += "fsdb_http_request_duration_seconds_count{" + labels + "} " + std::to_string(h.count) + "\n";
    }
    out += "# HELP fsdb_rejected_requests_total Requests refused, by cause (the error code).\n";
    out += "# TYPE fsdb_rejected_requests_total counter\n";
    for (const auto& [code, n] : rejected_)
      out += "fsdb_rejected_requests_total{cause=\"" + label(code) + "\"} " + std::to_string(n) + "\n";
  }
  for (const MetricGauge& g : gauges) {
    out += "# HELP " + g.name + " " + g.help + "\n# TYPE " + g.name + " " + g.type + "\n";
    out += g.name + " " + number(g.value) + "\n";
  }
  return out;
}

}  // namespace fsdb
