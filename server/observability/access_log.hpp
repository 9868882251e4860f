#pragma once
// One log line per answered request, at info level, for one request in `sample_every` (0: none) in the
// order they arrive; a 5xx answer is always logged, at error level. Lines go through spdlog, so
// --log-level above info also silences the sampled ones. As text:
//   GET /api/v1/health 200 0.3 ms id=9f86d081884c7d65
// as JSON (--log-format json) the same message with the request's fields: request_id, method, path,
// route (the OpenAPI path of the route that answered, or null), status, duration_ms and client (its
// address).
#include <httplib.h>
#include <spdlog/logger.h>

#include <cstdint>
#include <memory>

#include "server/observability/log_format.hpp"

namespace lp::server {

class AccessLog {
 public:
  AccessLog(int64_t sample_every, LogFormat format);

  // After the response has been written, on the request's thread (http/request_context.hpp).
  void record(const httplib::Request& req, const httplib::Response& res, double seconds);

 private:
  bool sampled() const;

  const int64_t sample_every_;
  const LogFormat format_;
  const std::shared_ptr<spdlog::logger> logger_;
};

}  // namespace lp::server
