#pragma once
#include <optional>
#include <string_view>

#include "engine/core/vec3.hpp"

namespace lp {

// How an RGB radiance becomes the scalar that sampling and median cut weigh by.
enum class LuminanceMode { Average, Rec709 };

inline float luminance(Rgb c, LuminanceMode mode) {
  return mode == LuminanceMode::Average ? (c.x + c.y + c.z) * (1.0f / 3.0f)
                                        : 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

inline const char* luminance_mode_name(LuminanceMode m) { return m == LuminanceMode::Average ? "average" : "rec709"; }

inline std::optional<LuminanceMode> parse_luminance_mode(std::string_view s) {
  if (s == "average") return LuminanceMode::Average;
  if (s == "rec709") return LuminanceMode::Rec709;
  return std::nullopt;
}

}  // namespace lp
