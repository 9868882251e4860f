#pragma once
#include "engine/core/enum_table.hpp"
#include "engine/core/vec3.hpp"

namespace lp {

// How an RGB radiance becomes the scalar that sampling and median cut weigh by.
enum class LuminanceMode { Average, Rec709 };

inline float luminance(Rgb c, LuminanceMode mode) {
  return mode == LuminanceMode::Average ? (c.x + c.y + c.z) * (1.0f / 3.0f)
                                        : 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

constexpr auto enum_entries(LuminanceMode) {
  return std::to_array<EnumEntry<LuminanceMode>>(
      {{LuminanceMode::Average, "average"}, {LuminanceMode::Rec709, "rec709"}});
}

}  // namespace lp
