#pragma once
// A lat-long HDR environment map: the image, its radiometric summary, and a per-map cache of
// derived data (sampling distributions, summed-area tables, ...) built once and shared.
#include <any>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "engine/envmap/invalid_pixels.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"

namespace lp {

class EnvMapSampler;

class EnvMap {
 public:
  // Applies the invalid-pixel policy (see invalid_pixels.hpp); every derived quantity uses the result.
  // Throws lp::Error(InvalidData) for an empty map or, under Reject, a bad pixel.
  explicit EnvMap(Image image, InvalidPixelPolicy policy = kDefaultInvalidPixelPolicy);

  const Image& image() const { return image_; }
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }

  // Integral of radiance over the sphere: sum of L * pixel solid angle (exact per-row solid angle).
  Rgb power() const { return power_; }
  // What the policy changed on load.
  const InvalidPixelReport& invalid_pixels() const { return invalid_pixels_; }
  // Solid-angle-weighted mean radiance: power / (4 pi).
  Rgb mean_radiance() const;
  float max_luminance(LuminanceMode mode) const;

  // Radiance of the pixel containing the direction (nearest, the same grid as the sampling pdf).
  Rgb radiance(Vec3 direction) const;
  Rgb radiance(latlong::Uv uv) const;

  // The importance sampler for a luminance mode, built on first use and cached.
  std::shared_ptr<const EnvMapSampler> sampler(LuminanceMode mode) const;

  // Generic cache of derived data keyed by a string: `build` runs once per key (concurrent callers of
  // the same key wait for it; if it throws, a later call tries again). Thread-safe.
  template <class T>
  std::shared_ptr<const T> derived(const std::string& key, const std::function<std::shared_ptr<const T>()>& build) const {
    const std::any& value = derived_any(key, [&] { return std::any(build()); });
    return std::any_cast<std::shared_ptr<const T>>(value);
  }

 private:
  struct Slot {
    std::mutex mutex;
    std::shared_ptr<const std::any> value;
  };
  const std::any& derived_any(const std::string& key, const std::function<std::any()>& build) const;

  Image image_;
  Rgb power_;
  InvalidPixelReport invalid_pixels_;
  mutable std::mutex cache_mutex_;
  mutable std::map<std::string, std::shared_ptr<Slot>> cache_;
};

}  // namespace lp
