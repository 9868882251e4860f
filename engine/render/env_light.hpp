#pragma once
// The environment map as the scene's light at infinity: rotated about z by `rotation_deg` (a feature
// at azimuth phi in the map appears at phi + rotation in the world), scaled by `intensity`.
// Sampling: importance (a sampler over the importance grid, MIS-compensated unless the lighting turns
// it off: envmap.hpp, SamplerWeights) or uniform over the sphere.
//
// Two resolutions. The importance grid is the map, or for a map wider than
// Lighting::importance_max_width the first of its coarser levels (envmap_levels.hpp) that fits: light
// samples carry the grid's radiance and every lookup weighed by MIS reads the same grid, so both
// strategies integrate one function and the pdf is exactly proportional to it. Lookups MIS plays no
// part in (camera rays, rays leaving a smooth, delta surface) read the map at the level of their ray
// cone's footprint instead: a wide pixel or a curved mirror sees the mean of what it covers, not one
// aliased texel, and never a level coarser than the grid.
#include <memory>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_levels.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/render/path_sampler.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

// The luminance the map's importance sampling weighs pixels by.
inline constexpr LuminanceMode kImportanceLuminance = LuminanceMode::Average;

// The importance-grid pixel a direction falls in, located ahead of its use (its data is prefetched),
// with the direction's coordinates in the map for footprint lookups.
struct EnvPixel {
  int x = 0, y = 0;
  float sin_theta = 1;
  latlong::Uv uv;
};

struct LightSample {
  Vec3 direction;  // world, unit, towards the light
  Rgb radiance;
  float pdf = 0;  // solid angle
};

class EnvLight {
 public:
  EnvLight(std::shared_ptr<const EnvMap> map, const Lighting& lighting);

  // Radiance on the importance grid, nearest texel.
  Rgb radiance(Vec3 world_direction) const;
  Rgb radiance(const EnvPixel& p) const { return grid_->image().at(p.x, p.y) * intensity_; }
  // Mean radiance over a cone of full angle `spread` around the direction: trilinear between the
  // map's levels for that footprint, never coarser than the grid.
  Rgb radiance_over(const EnvPixel& p, float spread) const;
  // The map's own texel (level 0, nearest), for lookups with footprints off.
  Rgb radiance_sharp(const EnvPixel& p) const { return map_->radiance(p.uv) * intensity_; }

  LightSample sample_importance(Point2 u) const;
  LightSample sample_uniform(Point2 u) const;

  // The grid pixel of a direction, located (and its data prefetched) before the ray that may escape
  // that way is traced; then its radiance and importance pdf.
  EnvPixel locate(Vec3 world_direction) const;
  float importance_pdf(const EnvPixel& p) const {
    return importance_ ? importance_->pdf(p.x, p.y, p.sin_theta) : 0.0f;
  }
  float importance_pdf(Vec3 world_direction) const { return importance_pdf(locate(world_direction)); }

  // Map space (the lat-long frame) <-> world.
  Vec3 to_map(Vec3 w) const { return {cos_ * w.x + sin_ * w.y, -sin_ * w.x + cos_ * w.y, w.z}; }
  Vec3 to_world(Vec3 m) const { return {cos_ * m.x - sin_ * m.y, sin_ * m.x + cos_ * m.y, m.z}; }

  const EnvMap& map() const { return *map_; }
  const EnvMap& grid() const { return *grid_; }  // the level the importance grid is built on
  int grid_level() const { return levels_->coarsest(); }
  bool dark() const { return dark_; }  // the map is black everywhere
  float intensity() const { return intensity_; }

  // The bytes the grid of a width x height map takes beyond the map and its own sampler.
  static int64_t grid_memory_bytes(int width, int height, int max_width);

 private:
  std::shared_ptr<const EnvMap> map_;
  std::shared_ptr<const EnvMapLevels> levels_;
  std::shared_ptr<const EnvMap> grid_;               // map_ itself when it fits the grid's width
  std::shared_ptr<const EnvMapSampler> importance_;  // null unless importance sampling is used
  float intensity_;
  bool dark_ = false;
  float cos_, sin_;
};

}  // namespace lp::render
