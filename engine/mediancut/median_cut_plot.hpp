#pragma once
// Pictures of a median cut result (the seed's figure 8), as 8-bit RGB the size of the map:
// - regions: the tone-mapped map, every cut drawn one pixel wide in pure green and a pure red dot
//   at each light;
// - lights: black, with a dot at each light coloured by its power divided by the largest component
//   of any light's power (so the brightest light has a channel at 1), then tone mapped like the map:
//   at exposure 0 the brightest light is saturated; raise `exposure` to see dim ones.
// Dots are squares centred on the light's pixel, wrapping across the phi seam: 5 x 5 when regions
// average at least 400 pixels, else 3 x 3, so that they do not swallow small regions.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "engine/image/image_io.hpp"
#include "engine/mediancut/median_cut.hpp"

namespace lp {

enum class MedianCutStyle { Regions, Lights };

constexpr auto enum_entries(MedianCutStyle) {
  return std::to_array<EnumEntry<MedianCutStyle>>(
      {{MedianCutStyle::Regions, "regions"}, {MedianCutStyle::Lights, "lights"}});
}

// Upper bound of the memory either picture takes for a width x height map: its 8-bit pixels and the
// float image the light dots are drawn in.
inline int64_t median_cut_plot_bytes(int64_t width, int64_t height) {
  return (3 * int64_t(sizeof(float)) + 3) * width * height;
}

// `map` is the image the result was computed from.
std::vector<uint8_t> plot_median_cut(const Image& map, const MedianCutResult& result, MedianCutStyle style,
                                     const ToneMap& tone);

int median_cut_dot_half_size(int64_t pixel_count, size_t light_count);  // 2 (5 x 5) or 1 (3 x 3)

}  // namespace lp
