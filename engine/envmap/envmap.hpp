#pragma once
// A lat-long HDR environment map: the image, its radiometric summary, and a per-map cache of
// derived data (sampling distributions, summed-area tables, ...) built once and shared.
#include <any>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "engine/core/memory_budget.hpp"
#include "engine/envmap/invalid_pixels.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"

namespace lp {

class EnvMapSampler;

// What an importance sampler weighs pixels by: their radiance, or for MIS compensation (Karlik et al.
// 2019) only the part of it above the map's mean. A renderer that weighs light samples against BSDF
// samples by MIS does best with light samples that leave the map's uniform part to the BSDF, which
// samples it well, and go where the map is brighter than its mean.
enum class SamplerWeights { Radiance, MisCompensated };

class EnvMap {
 public:
  // Applies the invalid-pixel policy (see invalid_pixels.hpp); every derived quantity uses the result.
  // Throws lp::Error(InvalidData) for an empty map or, under Reject, a bad pixel. `fixed_before` is what
  // the policy changed in the file an image was converted from (engine/projection), added to the report.
  explicit EnvMap(Image image, InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy,
                  const InvalidPixelReport& fixed_before = {});

  const Image& image() const { return image_; }
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }

  // Integral of radiance over the sphere: sum of L * pixel solid angle (exact per-row solid angle).
  Rgb power() const { return power_; }
  static Rgb power_of(const Image& image);
  // What the policy changed on load.
  const InvalidPixelReport& invalid_pixels() const { return invalid_pixels_; }
  // Solid-angle-weighted mean radiance: power / (4 pi).
  Rgb mean_radiance() const;
  float max_luminance(LuminanceMode mode) const;

  // Radiance of the pixel containing the direction (nearest, the same grid as the sampling pdf).
  Rgb radiance(Vec3 direction) const;
  Rgb radiance(latlong::Uv uv) const;

  // The importance sampler for a luminance mode and weighting, built on first use and cached.
  std::shared_ptr<const EnvMapSampler> sampler(LuminanceMode mode,
                                               SamplerWeights weights = SamplerWeights::Radiance) const;

  // The budget the map's memory comes from: `image` holds the image's bytes, and derived data built
  // from now on reserves its own (see derived). Call before the map is shared.
  void account_memory(MemoryBudget budget, MemoryReservation image);
  // That budget (unlimited until account_memory): a map made from this one reserves from it too.
  const MemoryBudget& memory_budget() const { return budget_; }
  // Bytes reserved now for the image and the derived data in the cache.
  int64_t memory_bytes() const;
  static int64_t image_bytes(int64_t width, int64_t height) {
    return width * height * 3 * int64_t(sizeof(float));
  }

  // Generic cache of derived data keyed by a string: `build` runs once per key (concurrent callers of
  // the same key wait for it; if it throws, a later call tries again). Thread-safe. Small data only:
  // large data names its size (below).
  template <class T>
  std::shared_ptr<const T> derived(const std::string& key,
                                   const std::function<std::shared_ptr<const T>()>& build) const {
    return derived<T>(key, 0, build);
  }
  // The same for data of up to `bytes`: they are reserved from the map's budget before `build` runs
  // (throws MemoryBudgetError if refused), and the entry may be evicted, least recently used first,
  // when the budget needs room; its bytes return with its last user, and a later call builds it again.
  template <class T>
  std::shared_ptr<const T> derived(const std::string& key, int64_t bytes,
                                   const std::function<std::shared_ptr<const T>()>& build) const {
    const std::any value = derived_any(key, bytes, [&](std::shared_ptr<const MemoryReservation> memory) {
      auto owner = std::make_shared<Owned<T>>(Owned<T>{build(), std::move(memory)});
      return std::any(std::shared_ptr<const T>(owner, owner->value.get()));
    });
    return std::any_cast<std::shared_ptr<const T>>(value);
  }

 private:
  template <class T>
  struct Owned {  // derived data with its reservation, released together with the last user
    std::shared_ptr<const T> value;
    std::shared_ptr<const MemoryReservation> memory;
  };
  struct Cache;
  std::any derived_any(const std::string& key, int64_t bytes,
                       const std::function<std::any(std::shared_ptr<const MemoryReservation>)>& build) const;

  Image image_;
  Rgb power_;
  InvalidPixelReport invalid_pixels_;
  MemoryBudget budget_;  // unlimited until account_memory
  MemoryReservation image_memory_;
  std::shared_ptr<Cache> cache_;
};

}  // namespace lp
