#pragma once
// lightprobe-server --health-check URL|PATH: the server's own probe, so a container's HEALTHCHECK needs no
// curl. One GET; the exit status says whether it answered 200 in time. A PATH probes the server the same
// configuration describes (its --host and --port, from flags or LIGHTPROBE_ variables), so an image's
// health check follows LIGHTPROBE_PORT.
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

// What --health-check's argument names: a URL as above, or a PATH ("/...") on the server listening on
// `host`:`port` (an any-address host probed on loopback). Throws std::invalid_argument naming the
// argument for anything else, or a PATH with port 0.
HealthCheckTarget health_check_target(const std::string& argument, const std::string& host, int port);

// GETs the target once: 0 if the answer is 200 within kHealthCheckTimeout, 1 otherwise. Says which on
// stdout (200) or stderr (anything else).
int run_health_check(const HealthCheckTarget& target);

}  // namespace lp::server
