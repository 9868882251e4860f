#pragma once
// What the server logs and how: the least severe level written, text or JSON lines, and the share of
// requests the access log keeps. The flag of that share is declared here.
#include <spdlog/common.h>

#include "api/parameters.hpp"
#include "server/observability/log_format.hpp"

namespace lp::server {

inline constexpr api::IntParameter kAccessLogSample{
    "access-log-sample",
    1,
    {0, int64_t{1} << 40},
    "access log: one line per N requests at info level, 0 for none; a 5xx answer is always logged, at error "
    "level"};

struct LogConfig {
  spdlog::level::level_enum level = spdlog::level::info;  // least severe messages written
  LogFormat format = LogFormat::Text;
  int64_t access_log_sample = kAccessLogSample.fallback;  // log 1 request in N (0: none; 5xx always)
};

}  // namespace lp::server
