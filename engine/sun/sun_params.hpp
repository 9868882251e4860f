#pragma once
// What counts as a sun (engine/sun/sun_extraction.hpp): a small disc far brighter than its surroundings.
// Its core is the connected pixels around a bright peak whose luminance is at least `threshold` times
// the peak's. It is a sun if that core fits in a cone of `max_radius_deg`, its mean radiance above the
// sky around it is at least `min_contrast` times that sky's, it carries at least `min_share` of the
// map's luminous power, and its peak outshines everything else in the map (sun_detection.hpp).
#include <array>
#include <string>

#include "engine/core/limits.hpp"

namespace lp {

struct SunParams {
  double threshold = 0.05;
  double max_radius_deg = 5.0;
  double min_share = 0.005;
  double min_contrast = 8;

  // Each in its range, else lp::Error naming the field (under `prefix`).
  void validate(const std::string& prefix = "") const;
  std::string key() const;  // "threshold=0.05;max_radius_deg=5;min_share=0.005;min_contrast=8"
};

// Each parameter declared once: its name (in requests, answers and, with dashes, options), the member,
// its range and what it means. Parsers, messages, help and the OpenAPI check derive from this table.
struct SunField {
  const char* name;
  double SunParams::*member;
  Range<double> range;
  const char* help;
};

inline constexpr std::array<SunField, 4> kSunFields{{
    {"threshold", &SunParams::threshold, limits::kSunThreshold,
     "a pixel joins the sun's core at this fraction of the peak's luminance or more"},
    {"max_radius_deg", &SunParams::max_radius_deg, limits::kSunMaxRadiusDeg,
     "the largest sun: its core fits in a cone of this radius (degrees)"},
    {"min_share", &SunParams::min_share, limits::kSunMinShare,
     "the least fraction of the map's luminous power a sun carries"},
    {"min_contrast", &SunParams::min_contrast, limits::kSunMinContrast,
     "the least ratio of the sun's mean luminance over its cone (above the sky around it) to that sky's"},
}};

}  // namespace lp
