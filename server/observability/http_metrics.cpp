#include "server/observability/http_metrics.hpp"

#include <algorithm>

#include "server/http/probe_routes.hpp"

namespace lp::server {

void HttpMetrics::record(const std::string& method, const std::string& route, int status, double seconds) {
  const size_t bucket = size_t(std::lower_bound(kLatencyBuckets.begin(), kLatencyBuckets.end(), seconds) -
                               kLatencyBuckets.begin());
  std::lock_guard lock(mutex_);
  ++requests_[{method, route, status}];
  HistogramData& h = latency_[{method, route}];
  if (h.counts.empty()) h.counts.resize(kLatencyBuckets.size() + 1);
  ++h.counts[bucket];
  ++h.count;
  h.sum += seconds;
}

void HttpMetrics::write(PrometheusText& out) const {
  std::lock_guard lock(mutex_);
  out.family("lightprobe_http_requests_total", "counter",
             "Requests answered, by method, route (its OpenAPI path; static: a dashboard file; none: no "
             "route) and status.");
  for (const auto& [key, n] : requests_) {
    const auto& [method, route, status] = key;
    out.sample("lightprobe_http_requests_total",
               {{"method", method}, {"route", route}, {"status", std::to_string(status)}}, double(n));
  }
  out.family("lightprobe_http_request_duration_seconds", "histogram",
             "Seconds from a request's head to the end of its response (an event stream: its whole life), "
             "by method and route.");
  for (const auto& [key, h] : latency_)
    out.histogram("lightprobe_http_request_duration_seconds", {{"method", key.first}, {"route", key.second}},
                  kLatencyBuckets, h);
}

std::string method_label(const std::string& method) {
  for (const char* m : {"GET", "HEAD", "POST", "PUT", "DELETE", "CONNECT", "OPTIONS", "TRACE", "PATCH"})
    if (method == m) return method;
  return "other";
}

std::string route_label(const std::string& route, const std::string& path, int status) {
  if (!route.empty()) return route;
  return !is_api_path(path) && path != "/metrics" && status < 400 ? "static" : "none";
}

}  // namespace lp::server
