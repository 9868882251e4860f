#pragma once
// Counts of the requests the server answered, for GET /metrics: by method, route and status, and their
// latency as a histogram by method and route. The method is one HTTP defines or "other"; the route is the
// OpenAPI path of the route that answered
// ("/api/v1/envmaps/{id}", never the raw path), "static" for a dashboard file, or "none" (no route: an
// unknown path, a preflight, a refusal before routing), so the number of series stays bounded.
// Thread-safe.
#include <array>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>

#include "server/observability/prometheus_text.hpp"

namespace lp::server {

// Upper bounds of the latency buckets, in seconds.
inline constexpr std::array<double, 15> kLatencyBuckets = {0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25,
                                                           0.5,   1,      2.5,   5,    10,    30,   60};

class HttpMetrics {
 public:
  void record(const std::string& method, const std::string& route, int status, double seconds);
  // The lightprobe_http_requests_total and lightprobe_http_request_duration_seconds families.
  void write(PrometheusText& out) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::tuple<std::string, std::string, int>, uint64_t> requests_;  // (method, route, status)
  std::map<std::pair<std::string, std::string>, HistogramData> latency_;    // (method, route)
};

// The route label of a request (see above): `route` if a route answered it, else "static" or "none".
std::string route_label(const std::string& route, const std::string& path, int status);
// The method label: the method if HTTP defines it, else "other" (a client may send any token).
std::string method_label(const std::string& method);

}  // namespace lp::server
