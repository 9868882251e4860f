#include "server/observability/access_log.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "server/http/request_context.hpp"
#include "server/http/request_id.hpp"
#include "server/observability/logging.hpp"

namespace lp::server {
namespace {

// The members of the JSON line after its time and level, without the braces.
std::string json_members(const std::string& message, const httplib::Request& req,
                         const httplib::Response& res, const std::string& id, double ms) {
  const RequestContext& r = current_request();
  const nlohmann::ordered_json line = {
      {"message", message},
      {"request_id", id},
      {"method", req.method},
      {"path", req.path},
      {"route", r.route.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.route)},
      {"status", res.status},
      {"duration_ms", std::round(ms * 1000) / 1000},
      {"client", r.client}};
  const std::string text = line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return text.substr(1, text.size() - 2);
}

}  // namespace

AccessLog::AccessLog(int64_t sample_every, LogFormat format)
    : sample_every_(sample_every), format_(format), logger_(access_logger()) {}

// By the order requests arrive, not the order they end: a client that waits for each answer before its
// next request sees exactly one line in N of them, whatever the threads that answered.
bool AccessLog::sampled() const {
  return sample_every_ > 0 && current_request().arrival % uint64_t(sample_every_) == 0;
}

void AccessLog::record(const httplib::Request& req, const httplib::Response& res, double seconds) {
  const bool server_error = res.status >= 500;
  if (!sampled() && !server_error) return;
  const auto level = server_error ? spdlog::level::err : spdlog::level::info;
  if (!logger_->should_log(level)) return;
  const double ms = seconds * 1000;
  const std::string id = res.get_header_value(kRequestIdHeader);
  const std::string message = fmt::format("{} {} {} {:.1f} ms", req.method, req.path, res.status, ms);
  if (format_ == LogFormat::Json)
    logger_->log(level, "{}", json_members(message, req, res, id, ms));
  else
    logger_->log(level, "{} id={}", message, id);
}

}  // namespace lp::server
