#pragma once
// The map's sun as a light of its own (lighting.sun = extract; engine/sun/sun_extraction.hpp): the sun's
// power spread evenly over the cone of its angular radius r about its direction, so of radiance
// power / (2 pi (1 - cos r)) inside the cone. Sampled uniformly over the cone, weighed against BSDF
// sampling by MIS; the residual map is the environment the rest of the lighting comes from, and the two
// together light a scene as the map does.
#include <memory>
#include <optional>

#include "engine/core/point2.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/frame.hpp"
#include "engine/render/scene_desc.hpp"
#include "engine/sun/sun.hpp"

namespace lp::render {

class SunLight {
 public:
  // Rotated and scaled as `env` rotates and scales the map.
  SunLight(const Sun& sun, const EnvLight& env);

  LightSample sample(Point2 u) const;
  float pdf() const { return pdf_; }  // solid angle, inside the cone
  bool contains(Vec3 world_direction) const;
  Rgb radiance() const { return radiance_; }  // inside the cone

 private:
  Frame frame_;          // about the sun's direction
  float one_minus_cos_;  // 1 - cos r
  float chord_squared_;  // |d - axis|^2 at the cone's edge: 2 (1 - cos r)
  float pdf_;
  Rgb radiance_;
};

// The map a render's environment light samples, and its sun: with sun = extract and a sun found (default
// parameters), the residual map and the sun; otherwise the map itself and none.
struct SunSplit {
  std::shared_ptr<const EnvMap> environment;
  std::optional<Sun> sun;
};
SunSplit split_sun(std::shared_ptr<const EnvMap> map, const Lighting& lighting);

}  // namespace lp::render
