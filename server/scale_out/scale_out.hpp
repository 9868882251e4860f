#pragma once
// How this server splits its renders over machines (--redis): where Redis is, the size of a work item,
// and where workers fetch this server's maps and mesh bundles. None without --redis.
#include <optional>
#include <string>

#include "server/scale_out/mesh_bundles.hpp"
#include "server/scale_out/redis_url.hpp"
#include "server/scale_out/scale_out_config.hpp"
#include "server/scale_out/scale_out_counters.hpp"

namespace lp::server {

struct ScaleOut {
  RedisAddress redis;
  int item_spp = 0;
  std::string advertise_url;       // http://HOST:PORT of this server, for GET /api/v1/content/{hash}
  MeshBundles* bundles = nullptr;  // where a render publishes its scene's mesh bundles
  ScaleOutCounters* counters = nullptr;
};

inline std::optional<ScaleOut> scale_out(const ScaleOutConfig& c, MeshBundles& bundles,
                                         ScaleOutCounters& counters) {
  if (!c.redis || c.role == ServerRole::Worker) return std::nullopt;
  return ScaleOut{*c.redis, c.item_spp, c.advertise_url, &bundles, &counters};
}

}  // namespace lp::server
