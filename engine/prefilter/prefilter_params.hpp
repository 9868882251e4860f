#pragma once
// What a prefiltered specular chain is made of: its levels, their projection, sizes and roughness, and
// the GGX samples per texel. Roughness is perceptual, as in the DFG table (ibl/dfg_lut.hpp): alpha =
// roughness^2.
#include <string>

#include "engine/projection/projection.hpp"

namespace lp {

struct PrefilterParams {
  int levels = 6;       // level i has roughness i / (levels - 1); level 0 is the map itself, filtered
  int base_size = 256;  // the size of level 0 in its projection's terms (projection.hpp)
  int samples = 1024;   // GGX samples per texel of the levels above 0
  Projection projection = Projection::LatLong;

  // Throws lp::Error(InvalidArgument) naming the field (limits.hpp: kPrefilter*); levels is also at
  // most log2(base_size), so that the last level is at least 2 texels wide, and a cross's base_size a
  // multiple of 2^(levels - 1), so that every level is a cross of whole faces and a mip level of the
  // one before.
  void validate(const std::string& prefix = "") const;

  double roughness(int level) const { return levels > 1 ? double(level) / (levels - 1) : 0.0; }
  bool operator==(const PrefilterParams&) const = default;
};

// The size of level `level` in the projection's terms: base_size halved `level` times, rounded down (a
// lat-long width, the face of a cube or cross, the side of a square map).
int prefilter_level_size(const PrefilterParams& params, int level);
// The image of level `level`: projection_shape of its size (a cube is the strip of its six faces).
ImageShape prefilter_level_shape(const PrefilterParams& params, int level);

}  // namespace lp
