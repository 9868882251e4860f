#pragma once
// What a map's unusable pixel values become. Lossy codecs (OpenEXR's DWA and B44, JPEG-derived HDR
// pipelines) leave small negative values in real maps, and near a bright sun even Inf or NaN; every
// mainstream renderer loads such maps (pbrt clamps radiance at 0, Cycles zeroes non-finite pixels).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/image/image.hpp"

namespace lp {

// clamp: negative channel values become 0 and invalid pixels black; reject: the first bad pixel is an error.
enum class InvalidPixelPolicy { Clamp, Reject };
constexpr auto enum_entries(InvalidPixelPolicy) {
  return std::to_array<EnumEntry<InvalidPixelPolicy>>(
      {{InvalidPixelPolicy::Clamp, "clamp"}, {InvalidPixelPolicy::Reject, "reject"}});
}
inline constexpr InvalidPixelPolicy kDefaultInvalidPixelPolicy = InvalidPixelPolicy::Clamp;

// The largest channel value a map may hold. Real maps stay far below (the sun's disc is about 1.6e9
// cd/m2); above it, sums and ratios derived from the map (power, sampling weights over up to 2^32
// pixels, radiance / pdf) could overflow a float, so such a pixel counts as non-finite.
inline constexpr float kMaxRadiance = 1e24f;

struct InvalidPixelReport {
  size_t clamped_negative_values = 0;  // channel values below 0 set to 0
  float most_negative_value = 0.0f;    // the lowest of them before clamping (0 if none)
  size_t non_finite_pixels = 0;        // pixels with a NaN, Inf or over-kMaxRadiance channel, set to black
};

// Applies the policy in place, row by row from the top left. Under Reject throws lp::Error(InvalidData)
// naming the first bad pixel, its channel and value.
InvalidPixelReport sanitize_radiance(Image& image, InvalidPixelPolicy policy);

}  // namespace lp
