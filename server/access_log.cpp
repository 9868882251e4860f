#include "server/access_log.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace lp::server {
namespace {

using Clock = std::chrono::steady_clock;
thread_local Clock::time_point request_start;

}  // namespace

void AccessLog::start_request() {
  request_start = Clock::now();
}

bool AccessLog::sampled() {
  if (sample_every_ <= 0) return false;
  return seen_.fetch_add(1, std::memory_order_relaxed) % uint64_t(sample_every_) == 0;
}

void AccessLog::record(const httplib::Request& req, const httplib::Response& res) {
  const bool server_error = res.status >= 500;
  if (!sampled() && !server_error) return;
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - request_start).count();
  spdlog::log(server_error ? spdlog::level::err : spdlog::level::info, "{} {} {} {:.1f} ms", req.method,
              req.path, res.status, ms);
}

}  // namespace lp::server
