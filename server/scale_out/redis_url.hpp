#pragma once
// Where Redis listens, as --redis gives it: redis://HOST[:PORT].
#include <string>

namespace lp::server {

inline constexpr int kRedisDefaultPort = 6379;

struct RedisAddress {
  std::string host;  // an IPv6 address without its brackets
  int port = kRedisDefaultPort;
  std::string url() const;  // back to redis://HOST:PORT
};

// Splits redis://HOST[:PORT][/]; throws std::invalid_argument naming the URL and the form for anything
// else (other schemes, user names or passwords, database numbers, ports outside 1..65535).
RedisAddress parse_redis_url(const std::string& url);

}  // namespace lp::server
