#pragma once
#include "engine/core/enum_table.hpp"
#include "engine/core/vec3.hpp"

namespace lp {

// How an RGB radiance becomes the scalar that sampling and median cut weigh by.
enum class LuminanceMode { Average, Rec709 };

// The weights of linear R, G and B in the relative luminance of Rec. 709 (sRGB) primaries.
struct RgbWeights {
  double r, g, b;
};
inline constexpr RgbWeights kRec709Weights{0.2126, 0.7152, 0.0722};

inline float luminance(Rgb c, LuminanceMode mode) {
  if (mode == LuminanceMode::Average) return (c.x + c.y + c.z) * (1.0f / 3.0f);
  return float(kRec709Weights.r) * c.x + float(kRec709Weights.g) * c.y + float(kRec709Weights.b) * c.z;
}

constexpr auto enum_entries(LuminanceMode) {
  return std::to_array<EnumEntry<LuminanceMode>>(
      {{LuminanceMode::Average, "average"}, {LuminanceMode::Rec709, "rec709"}});
}

}  // namespace lp
