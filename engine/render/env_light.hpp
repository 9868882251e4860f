#pragma once
// The environment map as the scene's light at infinity: rotated about z by `rotation_deg` (a feature
// at azimuth phi in the map appears at phi + rotation in the world), scaled by `intensity`.
// Sampling: importance (the map's sampler for kImportanceLuminance) or uniform over the sphere.
#include <memory>

#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/render/path_sampler.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

// The luminance the map's importance sampling weighs pixels by.
inline constexpr LuminanceMode kImportanceLuminance = LuminanceMode::Average;

// The map pixel a direction falls in, located ahead of its use (its data is prefetched).
struct EnvPixel {
  int x = 0, y = 0;
  float sin_theta = 1;
};

struct LightSample {
  Vec3 direction;  // world, unit, towards the light
  Rgb radiance;
  float pdf = 0;  // solid angle
};

class EnvLight {
 public:
  EnvLight(std::shared_ptr<const EnvMap> map, const Lighting& lighting);

  Rgb radiance(Vec3 world_direction) const;

  LightSample sample_importance(Point2 u) const;
  LightSample sample_uniform(Point2 u) const;

  // The map pixel of a direction, located (and its data prefetched) before the ray that may escape
  // that way is traced; then its radiance and importance pdf.
  EnvPixel locate(Vec3 world_direction) const;
  Rgb radiance(const EnvPixel& p) const { return map_->image().at(p.x, p.y) * intensity_; }
  float importance_pdf(const EnvPixel& p) const {
    return importance_ ? importance_->pdf(p.x, p.y, p.sin_theta) : 0.0f;
  }
  float importance_pdf(Vec3 world_direction) const { return importance_pdf(locate(world_direction)); }

  // Map space (the lat-long frame) <-> world.
  Vec3 to_map(Vec3 w) const { return {cos_ * w.x + sin_ * w.y, -sin_ * w.x + cos_ * w.y, w.z}; }
  Vec3 to_world(Vec3 m) const { return {cos_ * m.x - sin_ * m.y, sin_ * m.x + cos_ * m.y, m.z}; }

  const EnvMap& map() const { return *map_; }
  bool dark() const { return dark_; }  // the map is black everywhere
  float intensity() const { return intensity_; }

 private:
  std::shared_ptr<const EnvMap> map_;
  std::shared_ptr<const EnvMapSampler> importance_;  // null unless importance sampling is used
  float intensity_;
  bool dark_ = false;
  float cos_, sin_;
};

}  // namespace lp::render
