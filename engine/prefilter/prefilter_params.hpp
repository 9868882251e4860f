#pragma once
// What a prefiltered specular chain is made of: its levels, their projection, sizes and roughness, and
// the GGX samples per texel. Roughness is perceptual, as in the DFG table (ibl/dfg_lut.hpp): alpha =
// roughness^2.
#include <string>

#include "engine/core/enum_table.hpp"
#include "engine/projection/projection.hpp"

namespace lp {

// How the roughness of level i follows from i: the schedule an engine reads its levels with (linear as
// glTF's KHR_lights_environment, Filament's, Babylon's HDRFiltering; level_roughness_formula says each).
enum class LevelRoughness { Linear, Filament, Babylon };
constexpr auto enum_entries(LevelRoughness) {
  return std::to_array<EnumEntry<LevelRoughness>>({{LevelRoughness::Linear, "linear"},
                                                   {LevelRoughness::Filament, "filament"},
                                                   {LevelRoughness::Babylon, "babylon"}});
}
// The schedule's formula in words, for conventions and manifests.
const char* level_roughness_formula(LevelRoughness schedule);

struct PrefilterParams {
  int levels = 6;       // level 0 is the map itself, filtered; level i has roughness(i)
  int base_size = 256;  // the size of level 0 in its projection's terms (projection.hpp)
  int samples = 1024;   // GGX samples per texel of the levels above 0
  Projection projection = Projection::LatLong;
  LevelRoughness level_roughness = LevelRoughness::Linear;

  // Throws lp::Error(InvalidArgument) naming the field (limits.hpp: kPrefilter*); levels is also at
  // most prefilter_max_levels, and a cross's base_size a
  // multiple of 2^(levels - 1), so that every level is a cross of whole faces and a mip level of the
  // one before.
  void validate(const std::string& prefix = "") const;

  // The perceptual roughness of level `level` under level_roughness (0 for level 0, in [0, 1]; above 1
  // for the levels Babylon filters at alpha above 1).
  double roughness(int level) const;
  bool operator==(const PrefilterParams&) const = default;
};

// The most levels a chain from base_size has: log2(base_size), so that the last level is at least 2
// texels wide (a lat-long one 2 x 1), or for a cube log2(base_size) + 1, the full pyramid to 1 x 1 faces.
int prefilter_max_levels(Projection projection, int base_size);
// The size of level `level` in the projection's terms: base_size halved `level` times, rounded down (a
// lat-long width, the face of a cube or cross, the side of a square map).
int prefilter_level_size(const PrefilterParams& params, int level);
// The image of level `level`: projection_shape of its size (a cube is the strip of its six faces).
ImageShape prefilter_level_shape(const PrefilterParams& params, int level);

}  // namespace lp
