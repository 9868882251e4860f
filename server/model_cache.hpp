#pragma once
// Models loaded for render requests, kept between requests: one per file, keyed by its path,
// modification time and size, so that a file replaced on disk is loaded again. A model's bytes
// (geometry and textures, Model::memory_bytes) are a cache entry of the memory budget: the budget
// evicts the least recently used model to make room, and the bytes return once the last render holding
// the model ends. Textures are shared between the models that use the same image file. Thread-safe.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "engine/core/memory_budget.hpp"
#include "engine/model/model.hpp"
#include "engine/texture/texture_cache.hpp"

namespace lp::server {

class ModelCache {
 public:
  explicit ModelCache(const MemoryBudget& budget);

  // The model of the file as it is now: the cached one, or load_model()'s. Throws lp::Error naming
  // what is wrong with the file, or MemoryBudgetError when the loaded model does not fit the budget.
  std::shared_ptr<const Model> get(const std::filesystem::path& path, const ModelLimits& limits);
  // Models in the cache now.
  size_t size() const;

 private:
  struct Version {
    std::filesystem::file_time_type modified;
    uintmax_t size = 0;
    bool operator==(const Version&) const = default;
  };
  // A model and the budget's bytes for it, released together with the model's last user.
  struct HeldModel {
    Model model;
    MemoryReservation memory;
  };
  struct Entry {
    Version version;
    std::shared_ptr<const HeldModel> held;
  };
  struct Shelf {
    std::mutex mutex;
    std::map<std::filesystem::path, Entry> entries;
    // Drops the entry of `path` if it still holds `held` (a newer load of the file stays).
    void evict(const std::filesystem::path& path, const HeldModel* held);
  };

  std::shared_ptr<const HeldModel> load(const std::filesystem::path& path, const ModelLimits& limits);

  const MemoryBudget& budget_;
  TextureCache textures_;
  std::shared_ptr<Shelf> shelf_ = std::make_shared<Shelf>();
};

}  // namespace lp::server
