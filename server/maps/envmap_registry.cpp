#include "server/maps/envmap_registry.hpp"

#include "api/api_error.hpp"

namespace lp::server {

std::shared_ptr<const EnvMapEntry> EnvMapRegistry::add(const std::string& name, std::string format,
                                                       std::string source, std::shared_ptr<const EnvMap> map,
                                                       Projection source_projection) {
  auto entry = std::make_shared<EnvMapEntry>(EnvMapEntry{name, name, std::move(format), std::move(source),
                                                         std::move(map), std::chrono::system_clock::now(),
                                                         source_projection});
  std::lock_guard lock(mutex_);
  if (entries_.count(name))
    throw api::ApiError(api::ErrorCode::Conflict, "an environment map named '" + name + "' exists");
  if (int64_t(entries_.size()) >= max_entries_)
    throw api::ApiError(api::ErrorCode::InsufficientStorage, "the server holds the maximum number of maps (" +
                                                                 std::to_string(max_entries_) +
                                                                 "); delete one first");
  entries_.emplace(name, entry);
  return entry;
}

std::shared_ptr<const EnvMapEntry> EnvMapRegistry::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto it = entries_.find(id);
  return it == entries_.end() ? nullptr : it->second;
}

std::shared_ptr<const EnvMapEntry> EnvMapRegistry::get(const std::string& id) const {
  auto entry = find(id);
  if (!entry) throw api::not_found("no environment map with id '" + api::excerpt(id) + "'");
  return entry;
}

bool EnvMapRegistry::remove(const std::string& id) {
  std::lock_guard lock(mutex_);
  return entries_.erase(id) > 0;
}

std::vector<std::shared_ptr<const EnvMapEntry>> EnvMapRegistry::list() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<const EnvMapEntry>> out;
  for (const auto& [id, e] : entries_) out.push_back(e);
  return out;
}

}  // namespace lp::server
