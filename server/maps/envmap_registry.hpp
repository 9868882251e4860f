#pragma once
// The loaded environment maps, by id: the map names (server/storage/resource_name.hpp). Handlers hold a
// shared_ptr while they work, so a DELETE never pulls a map out from under a running request.
#include <chrono>
#include <memory>
#include <string>

#include "api/parameters.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/projection/projection.hpp"
#include "server/storage/named_registry.hpp"

namespace lp::server {

inline constexpr api::IntParameter kMaxEnvmaps{"max-envmaps", 64, {1, 100000}, "most maps held at once"};

struct EnvMapEntry {
  std::string id;
  std::string name;
  std::string format;  // "exr", "pfm", "hdr" or "procedural"
  std::string source;  // "upload", "path:<relative>", "procedural"
  std::shared_ptr<const EnvMap> map;
  std::chrono::system_clock::time_point created;
  Projection source_projection = Projection::LatLong;  // the file's layout, converted to lat-long on load
};

class EnvMapRegistry : public NamedRegistry<EnvMapEntry> {
 public:
  explicit EnvMapRegistry(int64_t max_entries);

  // Throws ApiError 409 if the name is taken, 507 when full.
  std::shared_ptr<const EnvMapEntry> add(const std::string& name, std::string format, std::string source,
                                         std::shared_ptr<const EnvMap> map,
                                         Projection source_projection = Projection::LatLong);
};

}  // namespace lp::server
