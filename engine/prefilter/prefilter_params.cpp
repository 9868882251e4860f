#include "engine/prefilter/prefilter_params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "engine/core/validate.hpp"

namespace lp {

void PrefilterParams::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "base_size"), base_size, limits::kPrefilterBaseSize);
  require_in(field_path(prefix, "samples"), samples, limits::kPrefilterSamples);
  require_in(field_path(prefix, "levels"), levels, limits::kPrefilterLevels);
  const int most = std::bit_width(unsigned(base_size)) - 1;
  require(
      levels <= most, field_path(prefix, "levels"),
      fmt::format("must be at most log2(base_size) = {} for base_size {}, got {}", most, base_size, levels));
  const int step = 1 << (levels - 1);
  require(projection != Projection::Cross || base_size % step == 0, field_path(prefix, "base_size"),
          fmt::format("must be a multiple of 2^(levels - 1) = {} for a cross of {} levels, got {}", step,
                      levels, base_size));
}

int prefilter_level_size(const PrefilterParams& params, int level) {
  return std::max(1, params.base_size >> level);
}

ImageShape prefilter_level_shape(const PrefilterParams& params, int level) {
  return projection_shape(params.projection, prefilter_level_size(params, level));
}

}  // namespace lp
