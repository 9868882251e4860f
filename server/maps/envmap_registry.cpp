#include "server/maps/envmap_registry.hpp"

namespace lp::server {

EnvMapRegistry::EnvMapRegistry(int64_t max_entries)
    : NamedRegistry(max_entries, {"an environment map", "environment map", "with id",
                                  "maps (" + std::to_string(max_entries) + ")"}) {}

std::shared_ptr<const EnvMapEntry> EnvMapRegistry::add(const std::string& name, std::string format,
                                                       std::string source, std::shared_ptr<const EnvMap> map,
                                                       Projection source_projection) {
  return NamedRegistry::add(name,
                            EnvMapEntry{name, name, std::move(format), std::move(source), std::move(map),
                                        std::chrono::system_clock::now(), source_projection});
}

}  // namespace lp::server
