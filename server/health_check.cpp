#include "server/health_check.hpp"

#include <fmt/format.h>
#include <httplib.h>

#include <iostream>
#include <regex>
#include <stdexcept>

namespace lp::server {

HealthCheckTarget parse_health_check_url(const std::string& url) {
  static const std::regex form(
      R"(http://(?:\[([0-9A-Fa-f:.]+)\]|([^/?#:\[\]@]+))(?::(\d{1,5}))?([/?][^#]*)?)");
  std::smatch m;
  const auto invalid = [&] {
    return std::invalid_argument(
        fmt::format("--health-check takes a URL http://HOST[:PORT][/PATH], got '{}'", url));
  };
  if (!std::regex_match(url, m, form)) throw invalid();
  HealthCheckTarget target;
  target.host = m[1].matched ? m[1].str() : m[2].str();
  if (m[3].matched) target.port = std::stoi(m[3].str());
  if (target.port < 1 || target.port > 65535) throw invalid();
  const std::string path = m[4].str();  // empty, "/..." or "?..."
  target.path = path.starts_with('/') ? path : "/" + path;
  return target;
}

HealthCheckTarget health_check_target(const std::string& argument, const std::string& host, int port) {
  if (!argument.starts_with('/')) return parse_health_check_url(argument);
  if (port == 0)
    throw std::invalid_argument(fmt::format("--health-check {} needs the server's --port, not 0", argument));
  const std::string local = host == "0.0.0.0" || host.empty() ? "127.0.0.1" : host == "::" ? "::1" : host;
  return {local, port, argument};
}

int run_health_check(const HealthCheckTarget& target) {
  const bool v6 = target.host.find(':') != std::string::npos;
  const std::string url = fmt::format("http://{}{}{}:{}{}", v6 ? "[" : "", target.host, v6 ? "]" : "",
                                      target.port, target.path);
  httplib::Client client(target.host, target.port);
  const auto timeout = std::chrono::duration_cast<std::chrono::seconds>(kHealthCheckTimeout).count();
  client.set_connection_timeout(timeout);
  client.set_read_timeout(timeout);
  client.set_write_timeout(timeout);
  const httplib::Result result = client.Get(target.path);
  if (!result) {
    std::cerr << fmt::format("health check {}: no answer ({})\n", url, httplib::to_string(result.error()));
    return 1;
  }
  if (result->status != 200) {
    std::cerr << fmt::format("health check {}: status {}\n", url, result->status);
    return 1;
  }
  std::cout << fmt::format("health check {}: status 200\n", url);
  return 0;
}

}  // namespace lp::server
