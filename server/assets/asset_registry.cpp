#include "server/assets/asset_registry.hpp"

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "server/storage/resource_name.hpp"

namespace lp::server {

PendingAsset::~PendingAsset() {
  if (!added_) registry_->release(name_);
}

std::shared_ptr<const api::AssetInfo> PendingAsset::add(api::AssetInfo info) {
  info.name = name_;
  auto entry = registry_->add(std::move(info));
  added_ = true;
  return entry;
}

std::unique_ptr<PendingAsset> AssetRegistry::hold(const std::string& name) {
  if (!valid_resource_name(name)) throw api::invalid_field("name", std::string(kResourceNameRule));
  std::lock_guard lock(mutex_);
  if (entries_.count(name) || pending_.count(name))
    throw api::ApiError(api::ErrorCode::Conflict, "an asset named '" + name + "' exists");
  if (int64_t(entries_.size() + pending_.size()) >= max_entries_)
    throw api::ApiError(api::ErrorCode::InsufficientStorage,
                        "the server holds the maximum number of assets (--" +
                            std::string(api::kMaxAssets.flag) + " " + std::to_string(max_entries_) +
                            "); delete one first");
  pending_.insert(name);
  return std::make_unique<PendingAsset>(*this, name);
}

std::shared_ptr<const api::AssetInfo> AssetRegistry::add(api::AssetInfo info) {
  auto entry = std::make_shared<const api::AssetInfo>(std::move(info));
  std::lock_guard lock(mutex_);
  pending_.erase(entry->name);
  entries_[entry->name] = entry;
  return entry;
}

void AssetRegistry::release(const std::string& name) {
  std::lock_guard lock(mutex_);
  pending_.erase(name);
}

std::shared_ptr<const api::AssetInfo> AssetRegistry::find(const std::string& name) const {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(name);
  return it == entries_.end() ? nullptr : it->second;
}

std::shared_ptr<const api::AssetInfo> AssetRegistry::get(const std::string& name) const {
  auto entry = find(name);
  if (!entry) throw api::not_found("no asset named '" + api::excerpt(name) + "'");
  return entry;
}

bool AssetRegistry::remove(const std::string& name) {
  std::lock_guard lock(mutex_);
  return entries_.erase(name) > 0;
}

std::vector<std::shared_ptr<const api::AssetInfo>> AssetRegistry::list() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<const api::AssetInfo>> out;
  for (const auto& [name, entry] : entries_) out.push_back(entry);
  return out;
}

}  // namespace lp::server
