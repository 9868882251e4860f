#include "server/scale_out/scale_out_config.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace lp::server {
namespace {

// The file's text without the line break that ends it.
std::string read_password(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("--redis-password-file: cannot read {}", file));
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (text.ends_with('\n')) text.pop_back();
  if (text.ends_with('\r')) text.pop_back();
  if (text.empty()) throw std::invalid_argument(fmt::format("--redis-password-file: {} is empty", file));
  return text;
}

void check_readable(const char* flag, const std::string& file) {
  if (!file.empty() && !std::ifstream(file))
    throw std::invalid_argument(fmt::format("--{}: cannot read {}", flag, file));
}

}  // namespace

void complete_redis(ScaleOutConfig& c, const std::optional<std::string>& password_variable) {
  const bool variable = password_variable && !password_variable->empty();
  struct Given {
    const char* name;
    bool given;
    bool tls;  // only for rediss://
  };
  const std::vector<Given> needing_redis = {{"--redis-password-file", !c.redis_password_file.empty(), false},
                                            {kRedisPasswordVariable, variable, false},
                                            {"--redis-tls-ca", !c.redis_tls.ca.empty(), true},
                                            {"--redis-tls-cert", !c.redis_tls.cert.empty(), true},
                                            {"--redis-tls-key", !c.redis_tls.key.empty(), true}};
  for (const Given& g : needing_redis) {
    if (g.given && !c.redis) throw std::invalid_argument(fmt::format("{} needs --redis", g.name));
    if (g.given && g.tls && !c.redis->tls)
      throw std::invalid_argument(fmt::format("{} needs a rediss:// URL in --redis", g.name));
  }
  if (!c.redis) return;
  const int sources =
      int(c.redis->password.has_value()) + int(!c.redis_password_file.empty()) + int(variable);
  if (sources > 1)
    throw std::invalid_argument(fmt::format(
        "the Redis password comes from one of the --redis URL, --redis-password-file or {}; {} were given",
        kRedisPasswordVariable, sources));
  if (!c.redis_password_file.empty()) c.redis->password = read_password(c.redis_password_file);
  if (variable) c.redis->password = *password_variable;
  if (!c.redis->user.empty() && !c.redis->password)
    throw std::invalid_argument(fmt::format("--redis names the user {} but no password", c.redis->user));
  if (c.redis_tls.cert.empty() != c.redis_tls.key.empty())
    throw std::invalid_argument("--redis-tls-cert and --redis-tls-key go together");
  check_readable("redis-tls-ca", c.redis_tls.ca);
  check_readable("redis-tls-cert", c.redis_tls.cert);
  check_readable("redis-tls-key", c.redis_tls.key);
  c.redis->tls_files = c.redis_tls;
}

}  // namespace lp::server
