#include "engine/prefilter/prefilter_params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "engine/core/validate.hpp"
#include "engine/image/babylon_env.hpp"

namespace lp {

void PrefilterParams::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "base_size"), base_size, limits::kPrefilterBaseSize);
  require_in(field_path(prefix, "samples"), samples, limits::kPrefilterSamples);
  require_in(field_path(prefix, "levels"), levels, limits::kPrefilterLevels);
  const int most = prefilter_max_levels(projection, base_size);
  require(levels <= most, field_path(prefix, "levels"),
          fmt::format("must be at most {} = {} for base_size {}, got {}",
                      projection == Projection::Cube ? "log2(base_size) + 1" : "log2(base_size)", most,
                      base_size, levels));
  const int step = 1 << (levels - 1);
  require(projection != Projection::Cross || base_size % step == 0, field_path(prefix, "base_size"),
          fmt::format("must be a multiple of 2^(levels - 1) = {} for a cross of {} levels, got {}", step,
                      levels, base_size));
}

const char* level_roughness_formula(LevelRoughness schedule) {
  switch (schedule) {
    case LevelRoughness::Filament:
      return "level i of n has roughness 1 - sqrt(1 - i / (n - 1)), Filament's lod = (n - 1) r (2 - r)";
    case LevelRoughness::Babylon:
      return "level i of n has GGX alpha = 2^(i / 0.8) / base_size (Babylon's lodGenerationScale 0.8), "
             "roughness sqrt(alpha) (above 1 where alpha is, as HDRFiltering filters them), level 0 "
             "roughness 0";
    case LevelRoughness::Linear:
      break;
  }
  return "level i of n has roughness i / (n - 1): lod = roughness (n - 1)";
}

double PrefilterParams::roughness(int level) const {
  if (levels < 2 || level <= 0) return 0.0;
  const double t = double(level) / (levels - 1);
  switch (level_roughness) {
    case LevelRoughness::Filament:
      return 1 - std::sqrt(std::max(0.0, 1 - t));
    case LevelRoughness::Babylon:
      // Babylon's HDRFiltering: alpha = 2^(i / lodGenerationScale) / size, not clamped.
      return std::sqrt(std::exp2(level / kBabylonLodGenerationScale) / base_size);
    case LevelRoughness::Linear:
      break;
  }
  return t;
}

int prefilter_max_levels(Projection projection, int base_size) {
  const int log2 = std::bit_width(unsigned(base_size)) - 1;
  return projection == Projection::Cube ? log2 + 1 : log2;
}

int prefilter_level_size(const PrefilterParams& params, int level) {
  return std::max(1, params.base_size >> level);
}

ImageShape prefilter_level_shape(const PrefilterParams& params, int level) {
  return projection_shape(params.projection, prefilter_level_size(params, level));
}

}  // namespace lp
