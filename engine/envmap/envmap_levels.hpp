#pragma once
// Coarser copies of a lat-long map, for lookups that stand for a cone of directions rather than one
// (a camera pixel, a ray leaving a curved mirror). Level k + 1 halves level k (rounded down, at least
// 1) with an area box filter weighted by each row's solid angle, so every level keeps the map's power
// (integral of radiance over the sphere) exactly: a coarse texel is the solid-angle mean of what it
// covers, and the poles' thin rows count for what they are.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/image/image.hpp"

namespace lp {

class EnvMapLevels {
 public:
  // Levels 1..`coarsest` of `map` (level 0 is the map's own image, referred to, not copied).
  EnvMapLevels(const EnvMap& map, int coarsest);
  EnvMapLevels(const EnvMapLevels&) = delete;  // it points into itself
  EnvMapLevels& operator=(const EnvMapLevels&) = delete;
  // The bytes the levels above 0 take for a width x height map.
  static int64_t memory_bytes(int width, int height, int coarsest);
  // The finest level no wider than `max_width`.
  static int level_for_width(int width, int max_width);

  int coarsest() const { return int(images_.size()) - 1; }
  const Image& level(int k) const { return *images_[size_t(k)]; }
  // The coarsest level as a map of its own, its image the level's (no copy); null for level 0 alone.
  std::shared_ptr<const EnvMap> coarsest_map() const { return top_; }
  // Bilinear in level k, uv in [0, 1]^2 as latlong::uv gives (u wraps around the seam, v is clamped at
  // the poles).
  Rgb bilinear(int k, latlong::Uv uv) const;
  // Between the two levels around `level` (clamped to [0, coarsest]), bilinear in each.
  Rgb trilinear(latlong::Uv uv, float level) const;
  // The level whose texels span `angle` radians in theta (a cone's full angle), unclamped.
  float level_for_angle(float angle) const;

 private:
  const Image& base_;
  std::vector<Image> levels_;          // 1 .. coarsest - 1
  std::shared_ptr<const EnvMap> top_;  // the coarsest
  std::vector<const Image*> images_;   // 0 .. coarsest: base_, levels_, top_'s image
};

}  // namespace lp
