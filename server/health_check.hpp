#pragma once
// lightprobe-server --health-check URL: the server's own probe, so a container's HEALTHCHECK needs no
// curl. One GET; the exit status says whether it answered 200 in time.
#include <chrono>
#include <string>

namespace lp::server {

// How long the probe waits to connect, and then for the answer.
inline constexpr std::chrono::seconds kHealthCheckTimeout{2};

struct HealthCheckTarget {
  std::string host;  // an IPv6 address without its brackets
  int port = 80;
  std::string path;  // with the query, "/" when the URL has none
};

// Splits http://HOST[:PORT][/PATH]; throws std::invalid_argument naming the URL for anything else.
HealthCheckTarget parse_health_check_url(const std::string& url);

// GETs `url` once: 0 if the answer is 200 within kHealthCheckTimeout, 1 otherwise. Says which on
// stdout (200) or stderr (anything else).
int run_health_check(const std::string& url);

}  // namespace lp::server
