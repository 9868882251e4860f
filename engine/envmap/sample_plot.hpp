#pragma once
// Pictures of where samples fell (the seed's figures 6 and 7), as 8-bit RGB the size of the map.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/envmap/envmap_sampler.hpp"
#include "engine/image/image_io.hpp"

namespace lp {

// Upper bound of the memory either picture takes for a width x height map: its 8-bit pixels and the
// float image the windows are gathered in.
inline int64_t sample_plot_bytes(int64_t width, int64_t height) {
  return (3 * int64_t(sizeof(float)) + 3) * width * height;
}

// The tone-mapped map with a 5x5 pure-blue square centred on each sampled pixel.
std::vector<uint8_t> plot_sample_marks(const EnvMap& map, std::span<const EnvSample> samples,
                                       const ToneMap& tone);
// Black except a 5x5 window of the map's own radiance around each sample, then tone mapped.
std::vector<uint8_t> plot_sample_windows(const EnvMap& map, std::span<const EnvSample> samples,
                                         const ToneMap& tone);

}  // namespace lp
