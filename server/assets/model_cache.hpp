#pragma once
// Models loaded for render requests, kept between requests: one per model path, used again while none
// of the files it was read from (the model file, an OBJ's material libraries and textures, a glTF's
// buffers and images: Model::files) has changed on disk, else loaded again. One load per path at a
// time: requests for a model being loaded wait for that load and share its model or its error.
// A load reserves from the memory budget, before it allocates each part, the most that part holds
// while loading (ModelLimits::reserve, from counts and image headers): a model that does not fit is
// refused before it is in memory. Once loaded, the model's bytes (geometry and textures,
// Model::memory_bytes) are a cache entry of the budget: the budget evicts the least recently used model
// to make room, and the bytes return once the last render holding the model ends.
// Textures are shared between the models that use the same image file. Models the engine builds itself
// (a scene preset's, kept for the whole process) are counted in the budget too, once. Thread-safe.
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>

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
  // Counts a model built by the engine and kept while the process lives (a scene preset's) in the
  // budget, the first time it is named: its bytes stay reserved from then on. Throws MemoryBudgetError,
  // naming `what`, when they do not fit (the next call tries again).
  void hold_builtin(std::shared_ptr<const Model> model, const std::string& what);
  // Models in the cache now.
  size_t size() const;

 private:
  // A model and the budget's bytes for it, released together with the model's last user.
  struct HeldModel {
    Model model;
    MemoryReservation memory;
  };
  using Loading = std::shared_future<std::shared_ptr<const HeldModel>>;
  struct Shelf {
    std::mutex mutex;
    std::map<std::filesystem::path, std::shared_ptr<const HeldModel>> entries;
    std::map<std::filesystem::path, Loading> loading;  // loads in flight
    // Drops the entry of `path` if it still holds `held` (a newer load of the file stays).
    void evict(const std::filesystem::path& path, const HeldModel* held);
  };
  struct Builtin {
    std::shared_ptr<const Model> model;
    MemoryReservation memory;
  };

  // The model of `path` from the load in flight, or from a new one this call makes.
  std::shared_ptr<const HeldModel> load_once(const std::filesystem::path& path, const ModelLimits& limits);
  std::shared_ptr<const HeldModel> load(const std::filesystem::path& path, const ModelLimits& limits);

  const MemoryBudget& budget_;
  TextureCache textures_;
  std::shared_ptr<Shelf> shelf_ = std::make_shared<Shelf>();
  std::mutex builtin_mutex_;
  std::map<const Model*, Builtin> builtins_;
};

}  // namespace lp::server
