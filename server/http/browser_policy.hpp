#pragma once
// What a web browser may ask of the server, as local development servers decide it. A page from any
// site can make the browser send requests to 127.0.0.1, and a DNS name rebound to 127.0.0.1 makes such
// a page same-origin. So the Host header must name this server (loopback, --host or --allowed-host),
// requests that change state (POST, DELETE) from a page of another origin are refused unless that
// origin is listed with --cors-origin, and listed origins get CORS headers and preflight answers.
#include <httplib.h>

#include <optional>
#include <string>
#include <vector>

#include "api/api_error.hpp"
#include "server/http/browser_policy_config.hpp"
#include "server/http/router.hpp"

namespace lp::server {

// How long a browser may keep a preflight's answer (Access-Control-Max-Age).
inline constexpr int kPreflightMaxAgeS = 600;

class BrowserPolicy {
 public:
  // `host`: the address the server listens on (--host).
  BrowserPolicy(const std::string& host, const BrowserPolicyConfig& config);

  // The refusal for a request (403 host_not_allowed / origin_not_allowed, 400 missing_host), if any.
  std::optional<api::ApiError> refusal(const httplib::Request& req) const;
  // For an origin listed with --cors-origin: its CORS headers (Allow-Origin, Expose-Headers), and true if
  // the request is a preflight (OPTIONS with Access-Control-Request-Method) of a route, now answered with
  // 204 (Allow-Methods: the route's, Allow-Headers, Max-Age). A preflight from another origin is answered
  // 403 origin_not_allowed (true). With listed origins (not *) every answer has Vary: Origin.
  bool answer_cors(const httplib::Request& req, httplib::Response& res, const Router& router) const;

 private:
  bool host_allowed(const std::string& host) const;
  bool cors_allowed(const std::string& origin) const;

  std::vector<std::string> hosts_;  // lower case, without brackets
  bool any_ip_literal_ = false;     // bound to every address: any IP literal names this server
  std::vector<std::string> cors_origins_;
};

}  // namespace lp::server
