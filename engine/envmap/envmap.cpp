#include "engine/envmap/envmap.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp {
namespace {

struct Power {
  double r = 0, g = 0, b = 0;
  Power operator+(const Power& o) const { return {r + o.r, g + o.g, b + o.b}; }
};

}  // namespace

Rgb EnvMap::power_of(const Image& image) {
  const int w = image.width(), h = image.height();
  const Power total = tbb::parallel_reduce(
      tbb::blocked_range<int>(0, h), Power{},
      [&](const tbb::blocked_range<int>& rows, Power acc) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
          const float* row = image.row(y);
          double r = 0, g = 0, b = 0;
          for (int x = 0; x < w; ++x) r += row[3 * x], g += row[3 * x + 1], b += row[3 * x + 2];
          const double omega = latlong::pixel_solid_angle(y, w, h);
          acc = acc + Power{r * omega, g * omega, b * omega};
        }
        return acc;
      },
      std::plus<Power>());
  return {float(total.r), float(total.g), float(total.b)};
}

EnvMap::EnvMap(Image image, InvalidPixelPolicy policy, const InvalidPixelReport& fixed_before)
    : image_(std::move(image)), cache_(std::make_shared<Cache>()) {
  if (image_.empty()) throw Error(ErrorKind::InvalidData, "environment map is empty");
  invalid_pixels_ = sanitize_radiance(image_, policy);
  invalid_pixels_.clamped_negative_values += fixed_before.clamped_negative_values;
  invalid_pixels_.non_finite_pixels += fixed_before.non_finite_pixels;
  invalid_pixels_.most_negative_value =
      std::min(invalid_pixels_.most_negative_value, fixed_before.most_negative_value);
  power_ = power_of(image_);
}

Rgb EnvMap::mean_radiance() const {
  return power_ / float(4.0 * kPi);
}

float EnvMap::max_luminance(LuminanceMode mode) const {
  const auto d = image_.data();
  float best = 0;
  for (size_t i = 0; i < d.size(); i += 3) best = std::max(best, luminance({d[i], d[i + 1], d[i + 2]}, mode));
  return best;
}

Rgb EnvMap::radiance(latlong::Uv uv) const {
  return image_.at(latlong::pixel_x(uv.u, width()), latlong::pixel_y(uv.v, height()));
}

Rgb EnvMap::radiance(Vec3 direction) const {
  return radiance(latlong::uv(direction));
}

std::shared_ptr<const EnvMapSampler> EnvMap::sampler(LuminanceMode mode, SamplerWeights weights) const {
  const bool compensated = weights == SamplerWeights::MisCompensated;
  return derived<EnvMapSampler>(
      std::string("sampler:") + enum_name(mode) + (compensated ? ":compensated" : ""),
      EnvMapSampler::memory_bytes(width(), height()),
      [&] { return std::make_shared<const EnvMapSampler>(*this, mode, weights); });
}

// The derived data by key. Shared with the eviction callbacks, which may outlive the map.
struct EnvMap::Cache {
  struct Slot {
    std::mutex mutex;  // held while the value is built
    std::any value;
    std::shared_ptr<const MemoryReservation> memory;  // null for untracked data
  };

  std::mutex mutex;
  std::map<std::string, std::shared_ptr<Slot>> slots;

  std::shared_ptr<Slot> slot(const std::string& key) {
    std::lock_guard lock(mutex);
    auto& entry = slots[key];
    if (!entry) entry = std::make_shared<Slot>();
    return entry;
  }
  // Drops the slot if it is still the one for `key`; its value goes with its last user.
  void evict(const std::string& key, const Slot* slot) {
    std::shared_ptr<Slot> dropped;
    std::lock_guard lock(mutex);
    auto it = slots.find(key);
    if (it == slots.end() || it->second.get() != slot) return;
    dropped = std::move(it->second);
    slots.erase(it);
  }
};

void EnvMap::account_memory(MemoryBudget budget, MemoryReservation image) {
  budget_ = std::move(budget);
  image_memory_ = std::move(image);
}

int64_t EnvMap::memory_bytes() const {
  int64_t bytes = image_memory_.bytes();
  std::lock_guard lock(cache_->mutex);
  for (const auto& [key, slot] : cache_->slots)
    if (slot->memory) bytes += slot->memory->bytes();
  return bytes;
}

std::any EnvMap::derived_any(
    const std::string& key, int64_t bytes,
    const std::function<std::any(std::shared_ptr<const MemoryReservation>)>& build) const {
  const auto slot = cache_->slot(key);
  std::lock_guard lock(slot->mutex);
  if (slot->value.has_value()) {
    if (slot->memory) slot->memory->touch();
    return slot->value;
  }
  std::shared_ptr<const MemoryReservation> memory;
  if (bytes > 0)
    memory = std::make_shared<const MemoryReservation>(
        budget_.reserve_cache(bytes, fmt::format("the {} data of a {}x{} map", key, width(), height()),
                              [cache = std::weak_ptr<Cache>(cache_), key, raw = slot.get()] {
                                if (const auto c = cache.lock()) c->evict(key, raw);
                              }));
  slot->value = build(memory);
  slot->memory = std::move(memory);
  return slot->value;
}

}  // namespace lp
