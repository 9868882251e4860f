#include "server/assets/model_cache.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

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
  held = load_once(path, limits);
  return std::shared_ptr<const Model>(held, &held->model);
}

std::shared_ptr<const ModelCache::HeldModel> ModelCache::load_once(const std::filesystem::path& path,
                                                                   const ModelLimits& limits) {
  std::promise<std::shared_ptr<const HeldModel>> promise;
  std::unique_lock lock(shelf_->mutex);
  // A model stored since the caller looked is from a load that began after the files were checked.
  if (const auto it = shelf_->entries.find(path); it != shelf_->entries.end()) return it->second;
  if (const auto it = shelf_->loading.find(path); it != shelf_->loading.end()) {
    const Loading loading = it->second;
    lock.unlock();
    return loading.get();  // rethrows the load's error
  }
  shelf_->loading.emplace(path, promise.get_future().share());
  lock.unlock();
  // Loaded without the lock, so that a slow load holds up no other; reserving may evict from this
  // cache, which takes the lock.
  std::shared_ptr<const HeldModel> held;
  try {
    held = load(path, limits);
  } catch (...) {
    lock.lock();
    shelf_->loading.erase(path);
    promise.set_exception(std::current_exception());
    throw;
  }
  lock.lock();
  shelf_->entries[path] = held;
  shelf_->loading.erase(path);
  promise.set_value(held);
  return held;
}

// Each part is reserved as the loader reaches it, and the whole returned when the load ends, when the
// loaded model's own bytes take their place. A model whose parts together exceed the whole budget can
// never load: that is said at once, not as a wait for memory.
std::shared_ptr<const ModelCache::HeldModel> ModelCache::load(const std::filesystem::path& path,
                                                              const ModelLimits& limits) {
  const std::string what = "the model " + path.filename().string();
  std::vector<MemoryReservation> parts;
  int64_t total = 0;
  ModelLimits counted = limits;
  counted.reserve = [&](int64_t bytes, const std::string& part) {
    total += bytes;
    if (total > budget_.capacity())
      throw MemoryBudgetError(fmt::format("not enough memory for {}: loading it needs at least {} (at {}), "
                                          "more than the whole {} budget",
                                          what, format_mib(total), part, format_mib(budget_.capacity())),
                              false);
    parts.push_back(budget_.reserve(bytes, MemoryUse::Transient, part + " of " + what));
  };
  auto held = std::make_shared<HeldModel>();
  held->model = load_model(path, counted, &textures_);
  parts.clear();
  held->memory = budget_.reserve_cache(held->model.memory_bytes(), what,
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
