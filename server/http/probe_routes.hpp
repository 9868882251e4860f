#pragma once
// The routes a process manager, load balancer or orchestrator probes: answered while the server is still
// loading at start and without a token (--auth-token-file).
#include <string_view>

#include "server/http/responses.hpp"

namespace lp::server {

inline constexpr std::string_view kHealthPath = "/api/v1/health";  // liveness: the process answers
inline constexpr std::string_view kReadyPath = "/api/v1/ready";    // readiness: maps and state loaded

inline bool is_probe(std::string_view path) {
  return path == kHealthPath || path == kReadyPath;
}

// The answer of the API while the server is loading at start: 503 not_ready, Retry-After: 1.
inline void send_not_ready(httplib::Response& res) {
  res.set_header("Retry-After", "1");
  send_error(res, api::ErrorCode::NotReady,
             "the server is starting: it is loading its maps and state directory (GET /api/v1/ready "
             "answers 200 once it is done)");
}

// The API's routes (the dashboard's static files and /metrics are not under it).
inline bool is_api_path(std::string_view path) {
  return path.starts_with("/api/");
}

}  // namespace lp::server
