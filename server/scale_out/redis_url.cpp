#include "server/scale_out/redis_url.hpp"

#include <fmt/format.h>

#include <regex>
#include <stdexcept>

namespace lp::server {

std::string RedisAddress::url() const {
  return host.find(':') == std::string::npos ? fmt::format("redis://{}:{}", host, port)
                                             : fmt::format("redis://[{}]:{}", host, port);
}

RedisAddress parse_redis_url(const std::string& url) {
  static const std::regex form(R"(redis://(?:\[([0-9A-Fa-f:.]+)\]|([A-Za-z0-9._-]+))(?::(\d{1,5}))?/?)");
  const auto invalid = [&] {
    return std::invalid_argument(fmt::format("--redis takes a URL redis://HOST[:PORT], got '{}'", url));
  };
  std::smatch m;
  if (url.size() > 300 || !std::regex_match(url, m, form)) throw invalid();
  RedisAddress address;
  address.host = m[1].matched ? m[1].str() : m[2].str();
  if (m[3].matched) address.port = std::stoi(m[3].str());
  if (address.port < 1 || address.port > 65535) throw invalid();
  return address;
}

}  // namespace lp::server
