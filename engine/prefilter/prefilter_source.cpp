#include "engine/prefilter/prefilter_source.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/envmap/latlong_resample.hpp"
#include "engine/prefilter/ggx_lobe_samples.hpp"

namespace lp {
namespace {

// A finer source would resolve lobes only chains of many thousand samples per texel can use, at four
// times the memory per step: 2048 x 1024 texels (0.18 degrees) are finer than level 1 of the widest chain.
constexpr int kMaxWidth = 2048;
constexpr float kLodBias = 1.0f;

// Levels down to a single texel.
int coarsest_level(int width, int height) {
  return std::max(EnvMapLevels::level_for_width(width, 1), EnvMapLevels::level_for_width(height, 1));
}

std::unique_ptr<const EnvMap> reduce(const EnvMap& map, int width) {
  if (width >= map.width()) return nullptr;
  return std::make_unique<const EnvMap>(resample_latlong(map.image(), width, std::max(1, width / 2)));
}

}  // namespace

PrefilterSource::PrefilterSource(const EnvMap& map, int width)
    : reduced_(reduce(map, width)),
      levels_(reduced_ ? *reduced_ : map, coarsest_level(reduced_ ? reduced_->width() : map.width(),
                                                         reduced_ ? reduced_->height() : map.height())) {
  const Image& base = levels_.level(0);
  const double texel = (2 * kPi / base.width()) * (kPi / base.height());
  half_log2_texel_ = float(0.5 * std::log2(texel));
}

int PrefilterSource::width_for(int map_width, const PrefilterParams& params) {
  if (params.levels < 2) return std::min(map_width, kMaxWidth);
  // lod >= 0 at the peak: 4 pi^2 / w^2 <= Omega_s 4^bias, with Omega_p of a w x w/2 map at the equator.
  const double omega = smallest_sample_solid_angle(params.roughness(1), params.samples);
  const double needed = 2 * kPi / std::sqrt(omega * std::exp2(2 * kLodBias));
  const auto width = std::bit_ceil(unsigned(std::clamp(std::ceil(needed), 1.0, double(kMaxWidth))));
  return std::min({int(width), map_width, kMaxWidth});
}

int64_t PrefilterSource::memory_bytes(int map_width, int map_height, int width) {
  int w = map_width, h = map_height;
  int64_t bytes = 0;
  if (width < map_width) {
    w = width, h = std::max(1, width / 2);
    bytes += resample_latlong_bytes(map_height, w, h);
  }
  // The levels, and while they are made two weighted RGBA levels (envmap_levels.cpp): levels 1 and 2,
  // 16 / 4 + 16 / 16 bytes a texel of the source, and a few rows.
  return bytes + EnvMapLevels::memory_bytes(w, h, coarsest_level(w, h)) + 5 * int64_t(w) * h;
}

float PrefilterSource::lod(float sample_solid_angle) const {
  return 0.5f * std::log2(sample_solid_angle) - half_log2_texel_ + kLodBias;
}

}  // namespace lp
