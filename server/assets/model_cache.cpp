#include "server/assets/model_cache.hpp"

#include <algorithm>

#include "engine/model/model_loader.hpp"

namespace lp::server {
namespace {

bool unchanged(const std::vector<FileStamp>& files) {
  return std::all_of(files.begin(), files.end(),
                     [](const FileStamp& file) { return FileStamp::of(file.path) == file; });
}

}  // namespace

ModelCache::ModelCache(const MemoryBudget& budget) : budget_(budget) {}

void ModelCache::Shelf::evict(const std::filesystem::path& path, const HeldModel* held) {
  std::lock_guard lock(mutex);
  const auto it = entries.find(path);
  if (it != entries.end() && it->second.get() == held) entries.erase(it);
}

std::shared_ptr<const Model> ModelCache::get(const std::filesystem::path& path, const ModelLimits& limits) {
  std::shared_ptr<const HeldModel> held;
  {
    std::lock_guard lock(shelf_->mutex);
    const auto it = shelf_->entries.find(path);
    if (it != shelf_->entries.end()) held = it->second;
  }
  if (held && unchanged(held->model.files)) {
    held->memory.touch();
    return std::shared_ptr<const Model>(held, &held->model);
  }
  // A stale model leaves the cache even if the files no longer load (renders holding it keep it).
  if (held) shelf_->evict(path, held.get());
  // Loaded without the lock, so that a slow load holds up no other; reserving may evict from this
  // cache, which takes the lock.
  held = load(path, limits);
  {
    std::lock_guard lock(shelf_->mutex);
    shelf_->entries[path] = held;
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

void ModelCache::hold_builtin(std::shared_ptr<const Model> model, const std::string& what) {
  std::lock_guard lock(builtin_mutex_);
  if (builtins_.contains(model.get())) return;
  MemoryReservation memory = budget_.reserve(model->memory_bytes(), MemoryUse::Held, what);
  const Model* key = model.get();
  builtins_.emplace(key, Builtin{std::move(model), std::move(memory)});
}

size_t ModelCache::size() const {
  std::lock_guard lock(shelf_->mutex);
  return shelf_->entries.size();
}

}  // namespace lp::server
