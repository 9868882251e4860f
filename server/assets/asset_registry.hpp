#pragma once
// The stored model assets, by name (server/storage/resource_name.hpp). Thread-safe. A name is held from the
// start of its upload, so two uploads of one name cannot both unpack, and uploads in flight count against
// --max-assets.
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "api/asset_schema.hpp"

namespace lp::server {

class AssetRegistry;

// A name held for an upload in progress; released on destruction unless the asset was added.
class PendingAsset {
 public:
  PendingAsset(AssetRegistry& registry, std::string name) : registry_(&registry), name_(std::move(name)) {}
  ~PendingAsset();
  PendingAsset(const PendingAsset&) = delete;
  PendingAsset& operator=(const PendingAsset&) = delete;

  const std::string& name() const { return name_; }
  // Registers the asset under the held name.
  std::shared_ptr<const api::AssetInfo> add(api::AssetInfo info);

 private:
  AssetRegistry* registry_;
  std::string name_;
  bool added_ = false;
};

class AssetRegistry {
 public:
  explicit AssetRegistry(int64_t max_entries) : max_entries_(max_entries) {}

  // Holds `name` for an upload: throws ApiError 400 for a bad name, 409 if it is taken or being
  // uploaded, 507 when the assets and uploads in flight reach the maximum.
  std::unique_ptr<PendingAsset> hold(const std::string& name);
  std::shared_ptr<const api::AssetInfo> find(const std::string& name) const;  // nullptr if absent
  std::shared_ptr<const api::AssetInfo> get(const std::string& name) const;   // throws ApiError 404
  bool remove(const std::string& name);
  std::vector<std::shared_ptr<const api::AssetInfo>> list() const;

 private:
  friend class PendingAsset;
  std::shared_ptr<const api::AssetInfo> add(api::AssetInfo info);
  void release(const std::string& name);

  int64_t max_entries_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const api::AssetInfo>> entries_;
  std::set<std::string> pending_;
};

}  // namespace lp::server
