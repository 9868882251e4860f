#include "server/http/browser_policy.hpp"

#include <arpa/inet.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "api/excerpt.hpp"
#include "server/http/vary.hpp"

namespace lp::server {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// "Example.org:8080" -> "example.org", "[::1]:80" -> "::1", "localhost." -> "localhost".
std::string host_name(const std::string& host_header) {
  std::string name = lower(host_header);
  if (name.starts_with('[')) return name.substr(1, name.find(']') - 1);
  name = name.substr(0, name.find(':'));
  if (name.ends_with('.')) name.pop_back();
  return name;
}

bool is_ip_literal(const std::string& name) {
  unsigned char address[16];
  return inet_pton(AF_INET, name.c_str(), address) == 1 || inet_pton(AF_INET6, name.c_str(), address) == 1;
}

bool changes_state(const std::string& method) {
  return method != "GET" && method != "HEAD" && method != "OPTIONS";
}

bool is_preflight(const httplib::Request& req) {
  return req.method == "OPTIONS" && req.has_header("Access-Control-Request-Method");
}

// The request headers a page may send beyond the CORS-safelisted ones.
constexpr const char* kAllowedHeaders = "Content-Type, Accept, Authorization, X-Request-Id, If-None-Match";
// The response headers a page may read beyond the CORS-safelisted ones.
constexpr const char* kExposedHeaders =
    "ETag, X-Request-Id, Retry-After, Location, WWW-Authenticate, X-Spp-Done, X-Sample-Count, "
    "X-Sample-Record-Layout";

}  // namespace

BrowserPolicy::BrowserPolicy(const std::string& host, const BrowserPolicyConfig& config)
    : hosts_{"localhost", "127.0.0.1", "::1"}, cors_origins_(config.cors_origins) {
  std::string bound = lower(host);
  if (bound.starts_with('[') && bound.ends_with(']')) bound = bound.substr(1, bound.size() - 2);
  any_ip_literal_ = bound.empty() || bound == "0.0.0.0" || bound == "::";
  if (!any_ip_literal_) hosts_.push_back(bound);
  for (const auto& name : config.allowed_hosts) hosts_.push_back(host_name(name));
}

bool BrowserPolicy::host_allowed(const std::string& host) const {
  return std::find(hosts_.begin(), hosts_.end(), host) != hosts_.end() ||
         (any_ip_literal_ && is_ip_literal(host));
}

bool BrowserPolicy::cors_allowed(const std::string& origin) const {
  return std::any_of(cors_origins_.begin(), cors_origins_.end(),
                     [&](const std::string& o) { return o == "*" || lower(o) == lower(origin); });
}

std::optional<api::ApiError> BrowserPolicy::refusal(const httplib::Request& req) const {
  const std::string host = req.get_header_value("Host");
  if (host.empty()) {
    if (req.version == "HTTP/1.0") return std::nullopt;
    return api::ApiError(api::ErrorCode::MissingHost, "an HTTP/1.1 request must have a Host header");
  }
  if (!host_allowed(host_name(host)))
    return api::ApiError(
        api::ErrorCode::HostNotAllowed,
        fmt::format("this server does not answer for host '{}'; start it with --allowed-host {} "
                    "to allow that name",
                    api::excerpt(host_name(host)), api::excerpt(host_name(host))));
  const std::string origin = req.get_header_value("Origin");
  if (origin.empty() || !changes_state(req.method) || lower(origin) == "http://" + lower(host) ||
      cors_allowed(origin))
    return std::nullopt;
  return api::ApiError(
      api::ErrorCode::OriginNotAllowed,
      fmt::format("pages from '{}' may not {} here; start the server with --cors-origin {} to "
                  "allow them",
                  api::excerpt(origin), req.method, api::excerpt(origin)));
}

bool BrowserPolicy::answer_cors(const httplib::Request& req, httplib::Response& res,
                                const Router& router) const {
  const bool any = std::find(cors_origins_.begin(), cors_origins_.end(), "*") != cors_origins_.end();
  if (!cors_origins_.empty() && !any) add_vary(res, "Origin");  // the answer depends on the Origin
  const std::string origin = req.get_header_value("Origin");
  if (origin.empty()) return false;
  if (!cors_allowed(origin)) {
    if (!is_preflight(req)) return false;
    send_error(res, api::ErrorCode::OriginNotAllowed,
               fmt::format("pages from '{}' may not call this server; start it with --cors-origin {} to "
                           "allow them",
                           api::excerpt(origin), api::excerpt(origin)));
    return true;
  }
  res.set_header("Access-Control-Allow-Origin", any ? "*" : origin);
  if (!is_preflight(req)) {
    res.set_header("Access-Control-Expose-Headers", kExposedHeaders);
    return false;
  }
  const auto methods = router.methods_for(req.path);
  if (methods.empty()) return false;
  std::string allowed;
  for (const auto& m : methods) allowed += (allowed.empty() ? "" : ", ") + m;
  res.set_header("Access-Control-Allow-Methods", allowed);
  res.set_header("Access-Control-Allow-Headers", kAllowedHeaders);
  res.set_header("Access-Control-Max-Age", std::to_string(kPreflightMaxAgeS));
  res.status = 204;
  return true;
}

}  // namespace lp::server
