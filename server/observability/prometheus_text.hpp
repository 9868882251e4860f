#pragma once
// The Prometheus text exposition format (version 0.0.4), as GET /metrics answers it: per metric family a
// "# HELP" and a "# TYPE" line, then its samples, `name{label="value",...} value`, one a line, every line
// ending in \n. Label values escape \, " and line feeds; help texts \ and line feeds.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lp::server {

inline constexpr const char* kPrometheusContentType = "text/plain; version=0.0.4; charset=utf-8";

using Labels = std::vector<std::pair<std::string, std::string>>;

// A histogram's observations: counts per bucket (not cumulative; the last one is above every bound), their
// number and their sum.
struct HistogramData {
  std::vector<uint64_t> counts;
  uint64_t count = 0;
  double sum = 0;
};

class PrometheusText {
 public:
  // Starts a family; its samples follow before the next family starts. `type`: counter, gauge, histogram.
  void family(std::string_view name, std::string_view type, std::string_view help);
  void sample(std::string_view name, const Labels& labels, double value);
  // name_bucket{...,le="b"} (cumulative, le="+Inf" last), name_sum and name_count.
  void histogram(std::string_view name, const Labels& labels, std::span<const double> bounds,
                 const HistogramData& data);

  const std::string& text() const { return out_; }

 private:
  std::string out_;
};

}  // namespace lp::server
