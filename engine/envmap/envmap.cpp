#include "engine/envmap/envmap.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "engine/core/error.hpp"
#include "engine/envmap/envmap_sampler.hpp"

namespace lp {
namespace {

struct Power {
  double r = 0, g = 0, b = 0;
  Power operator+(const Power& o) const { return {r + o.r, g + o.g, b + o.b}; }
};

Rgb compute_power(const Image& image) {
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

}  // namespace

EnvMap::EnvMap(Image image, InvalidPixelPolicy policy) : image_(std::move(image)) {
  if (image_.empty()) throw Error(ErrorKind::InvalidData, "environment map is empty");
  invalid_pixels_ = sanitize_radiance(image_, policy);
  power_ = compute_power(image_);
}

Rgb EnvMap::mean_radiance() const { return power_ / float(4.0 * kPi); }

float EnvMap::max_luminance(LuminanceMode mode) const {
  const auto d = image_.data();
  float best = 0;
  for (size_t i = 0; i < d.size(); i += 3) best = std::max(best, luminance({d[i], d[i + 1], d[i + 2]}, mode));
  return best;
}

Rgb EnvMap::radiance(latlong::Uv uv) const {
  return image_.at(latlong::pixel_x(uv.u, width()), latlong::pixel_y(uv.v, height()));
}

Rgb EnvMap::radiance(Vec3 direction) const { return radiance(latlong::uv(direction)); }

std::shared_ptr<const EnvMapSampler> EnvMap::sampler(LuminanceMode mode) const {
  return derived<EnvMapSampler>(std::string("sampler:") + luminance_mode_name(mode),
                                [&] { return std::make_shared<const EnvMapSampler>(*this, mode); });
}

const std::any& EnvMap::derived_any(const std::string& key, const std::function<std::any()>& build) const {
  std::shared_ptr<Slot> slot;
  {
    std::lock_guard lock(cache_mutex_);
    auto& entry = cache_[key];
    if (!entry) entry = std::make_shared<Slot>();
    slot = entry;
  }
  std::lock_guard lock(slot->mutex);
  if (!slot->value) slot->value = std::make_shared<const std::any>(build());
  return *slot->value;  // slots are never removed, so the reference outlives the lock
}

}  // namespace lp
