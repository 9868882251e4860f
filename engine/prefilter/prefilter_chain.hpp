#pragma once
// A prefiltered specular mip chain of a map, in any projection (engine/projection): level 0 is the map
// resampled to the base size (filtered, its power kept: resample_latlong for lat-long, reproject for
// the others), and level i > 0, half the size of level i - 1, holds at each texel the GGX convolution of
// params.roughness(i) in the texel's direction (lobe_convolution.hpp), read from the map by
// filtered importance sampling. Every level is evaluated at its own texels, never resampled from another
// projection. A cube's levels are strips of its six faces; a cross is made as that strip and laid out
// at the end, so its empty cells cost no work and stay black.
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image.hpp"
#include "engine/prefilter/prefilter_control.hpp"
#include "engine/prefilter/prefilter_params.hpp"

namespace lp {

struct PrefilteredChain {
  PrefilterParams params;
  int source_width = 0;       // the width of the map the lobes read (prefilter_source.hpp); 0 for one level
  std::vector<Image> levels;  // level 0 first, each of prefilter_level_shape
};

// The work units a chain reports through PrefilterControl: texel samples, a texel of level 0 counting one.
int64_t prefilter_work_units(const PrefilterParams& params);
// The bytes making a chain of a map_width x map_height map takes at most, the chain included.
int64_t prefilter_working_bytes(int map_width, int map_height, const PrefilterParams& params);
// The bytes of the chain itself.
int64_t prefiltered_chain_bytes(const PrefilterParams& params);

// Throws lp::Error(InvalidArgument) for parameters out of range; nullopt if the control stopped it.
std::optional<PrefilteredChain> prefilter_chain(const EnvMap& map, const PrefilterParams& params,
                                                const PrefilterControl& control = {});

}  // namespace lp
