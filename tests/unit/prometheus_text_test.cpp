// The Prometheus text format writer: escapes, numbers and histograms written as the format specifies.
#include "server/observability/prometheus_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace lp::server {
namespace {

TEST(PrometheusText, EscapesLabelValuesAndHelp) {
  PrometheusText out;
  out.family("x_total", "counter", "a \\ b\nc \"quoted\"");
  out.sample("x_total", {{"path", "a\"b\\c\nd"}, {"m", "GET"}}, 3);
  EXPECT_EQ(out.text(),
            "# HELP x_total a \\\\ b\\nc \"quoted\"\n"
            "# TYPE x_total counter\n"
            "x_total{path=\"a\\\"b\\\\c\\nd\",m=\"GET\"} 3\n");
}

TEST(PrometheusText, NumbersReadBackExactly) {
  PrometheusText out;
  const double inf = std::numeric_limits<double>::infinity();
  for (const double v : {0.0, 1024.0, 0.1, 1.0 / 3.0, 1e20, 12637437952.0, inf, -inf}) out.sample("v", {}, v);
  out.sample("v", {}, std::nan(""));
  EXPECT_EQ(out.text(),
            "v 0\nv 1024\nv 0.1\nv 0.3333333333333333\nv 1e+20\nv 12637437952\nv +Inf\nv -Inf\nv NaN\n");
}

TEST(PrometheusText, HistogramBucketsAreCumulative) {
  PrometheusText out;
  const std::vector<double> bounds = {0.5, 1};
  out.histogram("d", {{"r", "x"}}, bounds, {{2, 0, 3}, 5, 4.25});
  EXPECT_EQ(out.text(),
            "d_bucket{r=\"x\",le=\"0.5\"} 2\n"
            "d_bucket{r=\"x\",le=\"1\"} 2\n"
            "d_bucket{r=\"x\",le=\"+Inf\"} 5\n"
            "d_sum{r=\"x\"} 4.25\n"
            "d_count{r=\"x\"} 5\n");
}

}  // namespace
}  // namespace lp::server
