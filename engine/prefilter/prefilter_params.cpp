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
}

LevelSize latlong_level_size(int base_size, int level) {
  return {std::max(1, base_size >> level), std::max(1, (base_size / 2) >> level)};
}

}  // namespace lp
