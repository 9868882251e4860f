#include "engine/sun/sun_params.hpp"

#include <fmt/format.h>

#include "engine/core/validate.hpp"

namespace lp {

void SunParams::validate() const {
  require_in("threshold", threshold, limits::kSunThreshold);
  require_in("max_radius_deg", max_radius_deg, limits::kSunMaxRadiusDeg);
  require_in("min_share", min_share, limits::kSunMinShare);
}

std::string SunParams::key() const {
  return fmt::format("threshold={};max_radius_deg={};min_share={}", threshold, max_radius_deg, min_share);
}

}  // namespace lp
