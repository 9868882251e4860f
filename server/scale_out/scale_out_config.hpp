#pragma once
// Renders split over machines through Redis Streams (--redis): where Redis is, what this server does
// with it, where workers reach it, the size of a work item and how long a worker may hold one. The
// flags of the numbers are declared here.
#include <optional>
#include <string>

#include "api/parameters.hpp"
#include "server/scale_out/redis_url.hpp"
#include "server/scale_out/server_role.hpp"

namespace lp::server {

inline constexpr api::IntParameter kRedisItemSpp{
    "redis-item-spp",
    16,
    {1, 1 << 24},
    "samples per pixel of one work item of a render split over Redis (a 256x256 preset\nscene: about a "
    "second of one core)"};
inline constexpr api::IntParameter kRedisClaimTimeoutS{
    "redis-claim-timeout-s",
    30,
    {1, 86400},
    "seconds a worker may hold a work item before another worker takes it over (a worker\nthat died)"};

// The variable that gives --redis its password (kept off the command line, where every user sees it).
inline constexpr const char* kRedisPasswordVariable = "LIGHTPROBE_REDIS_PASSWORD";

struct ScaleOutConfig {
  std::optional<RedisAddress> redis;  // --redis; none: renders run in this process
  std::string redis_password_file;    // --redis-password-file
  RedisTlsFiles redis_tls;            // --redis-tls-ca, --redis-tls-cert, --redis-tls-key
  ServerRole role = ServerRole::Both;
  std::string advertise_url;  // where workers fetch maps from this server; empty: http://--host:port
  int item_spp = int(kRedisItemSpp.fallback);
  int claim_timeout_s = int(kRedisClaimTimeoutS.fallback);
};

// Gives --redis its password (from the URL, --redis-password-file or `password_variable`, the value of
// kRedisPasswordVariable: one of them) and its TLS files. Throws std::invalid_argument for a password
// given twice or a file that cannot be read, for these flags without --redis, and for TLS files without
// rediss://. No message holds the password.
void complete_redis(ScaleOutConfig& config, const std::optional<std::string>& password_variable);

}  // namespace lp::server
