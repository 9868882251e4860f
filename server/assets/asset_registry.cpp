#include "server/assets/asset_registry.hpp"

#include "api/api_error.hpp"
#include "server/assets/asset_limits.hpp"
#include "server/storage/resource_name.hpp"

namespace lp::server {

AssetRegistry::AssetRegistry(int64_t max_entries)
    : NamedRegistry(max_entries,
                    {"an asset", "asset", "named",
                     "assets (--" + std::string(kMaxAssets.flag) + " " + std::to_string(max_entries) + ")"}) {
}

std::unique_ptr<AssetRegistry::Hold> AssetRegistry::hold(const std::string& name) {
  if (!valid_resource_name(name)) throw api::invalid_field("name", std::string(kResourceNameRule));
  return NamedRegistry::hold(name);
}

}  // namespace lp::server
