#pragma once
// The radiance the lobes of a prefiltered chain read: the map, reduced (resample_latlong) to the
// resolution the densest lobe's samples can resolve, with its coarser power-keeping levels
// (envmap_levels.hpp). Filtered importance sampling (Krivanek and Colbert 2008): a sample that stands
// for a solid angle Omega_s reads, trilinearly, the level whose texels are that large,
//   lod = 1/2 log2(Omega_s / Omega_p) + 1,
// Omega_p the solid angle of a texel of the finest level at the equator; the 1 is their bias of one
// level, a little blur that keeps the pattern of the samples out of the result.
#include <cstdint>
#include <memory>

#include "engine/core/vec3.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_levels.hpp"
#include "engine/prefilter/prefilter_params.hpp"

namespace lp {

class PrefilterSource {
 public:
  // `map` must outlive the source when `width` is the map's own.
  PrefilterSource(const EnvMap& map, int width);

  // The width the levels of `params` need (at most the map's own, and at most 2048 texels): the
  // finest lobe's densest sample must not read below level 0.
  static int width_for(int map_width, const PrefilterParams& params);
  // The bytes a source of `width` made from a map_width x map_height map takes, while it is made.
  static int64_t memory_bytes(int map_width, int map_height, int width);

  int width() const { return levels_.level(0).width(); }
  float lod(float sample_solid_angle) const;
  Rgb radiance(Vec3 direction, float lod) const { return levels_.trilinear(latlong::uv(direction), lod); }

 private:
  std::unique_ptr<const EnvMap> reduced_;  // null when the map is read at its own resolution
  EnvMapLevels levels_;
  float half_log2_texel_ = 0;
};

}  // namespace lp
