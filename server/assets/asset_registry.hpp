#pragma once
// The stored model assets, by name (server/storage/resource_name.hpp). A name is held from the start of its
// upload, so two uploads of one name cannot both unpack, and uploads in flight count against --max-assets.
#include <memory>
#include <string>

#include "api/asset_schema.hpp"
#include "server/storage/named_registry.hpp"

namespace lp::server {

class AssetRegistry : public NamedRegistry<api::AssetInfo> {
 public:
  explicit AssetRegistry(int64_t max_entries);

  // Holds `name` for an upload: throws ApiError 400 for a bad name, 409 if it is taken or being
  // uploaded, 507 when the assets and uploads in flight reach the maximum.
  std::unique_ptr<Hold> hold(const std::string& name);
};

}  // namespace lp::server
