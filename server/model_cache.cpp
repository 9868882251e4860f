#include "server/model_cache.hpp"

#include <system_error>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"

namespace lp::server {

ModelCache::ModelCache(const MemoryBudget& budget) : budget_(budget) {}

void ModelCache::Shelf::evict(const std::filesystem::path& path, const HeldModel* held) {
  std::lock_guard lock(mutex);
  const auto it = entries.find(path);
  if (it != entries.end() && it->second.held.get() == held) entries.erase(it);
}

std::shared_ptr<const Model> ModelCache::get(const std::filesystem::path& path, const ModelLimits& limits) {
  std::error_code ec;
  Version version{std::filesystem::last_write_time(path, ec), 0};
  if (!ec) version.size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(ErrorKind::NotFound, "model not found: " + path.filename().string());
  std::shared_ptr<const HeldModel> held;
  {
    std::lock_guard lock(shelf_->mutex);
    const auto it = shelf_->entries.find(path);
    if (it != shelf_->entries.end() && it->second.version == version) held = it->second.held;
  }
  if (held) {
    held->memory.touch();
  } else {
    // Loaded without the lock, so that a slow load holds up no other; reserving may evict from this
    // cache, which takes the lock.
    held = load(path, limits);
    std::lock_guard lock(shelf_->mutex);
    shelf_->entries[path] = Entry{version, held};
  }
  return std::shared_ptr<const Model>(held, &held->model);
}

std::shared_ptr<const ModelCache::HeldModel> ModelCache::load(const std::filesystem::path& path,
                                                              const ModelLimits& limits) {
  auto held = std::make_shared<HeldModel>();
  held->model = load_model(path, limits, &textures_);
  held->memory = budget_.reserve_cache(held->model.memory_bytes(), "the model " + path.filename().string(),
                                       [shelf = std::weak_ptr<Shelf>(shelf_), path, raw = held.get()] {
                                         if (const auto s = shelf.lock()) s->evict(path, raw);
                                       });
  return held;
}

size_t ModelCache::size() const {
  std::lock_guard lock(shelf_->mutex);
  return shelf_->entries.size();
}

}  // namespace lp::server
