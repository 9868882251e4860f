#pragma once
// What a prefiltered specular chain is made of: its levels, their sizes and roughness, and the GGX
// samples per texel. Roughness is perceptual, as in the DFG table (ibl/dfg_lut.hpp): alpha = roughness^2.
#include <string>

namespace lp {

struct PrefilterParams {
  int levels = 6;       // level i has roughness i / (levels - 1); level 0 is the map itself, filtered
  int base_size = 256;  // the width of level 0 in texels
  int samples = 1024;   // GGX samples per texel of the levels above 0

  // Throws lp::Error(InvalidArgument) naming the field (limits.hpp: kPrefilter*); levels is also at
  // most log2(base_size), so that the last level is at least 2 texels wide.
  void validate(const std::string& prefix = "") const;

  double roughness(int level) const { return levels > 1 ? double(level) / (levels - 1) : 0.0; }
};

// Level `level` of a lat-long chain: the base halved `level` times, rounded down (the mip sizes of a
// texture whose level 0 is base_size x base_size / 2).
struct LevelSize {
  int width = 0, height = 0;
};
LevelSize latlong_level_size(int base_size, int level);

}  // namespace lp
