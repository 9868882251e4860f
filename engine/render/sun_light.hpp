#pragma once
// The map's sun as a light of its own (lighting.sun = extract; engine/sun/sun_extraction.hpp): the sun's
// power spread evenly over the cone of its angular radius r about its direction, so of radiance
// power / (2 pi (1 - cos r)) inside the cone. Sampled uniformly over the cone; the residual map is the
// environment the rest of the lighting comes from, and the two together light a scene as the map does.
// A light sample goes to the sun or to the residual map by a choice (one shadow ray a bounce, as without
// a sun) whose probability follows what each gives a surface of that normal: the sun's irradiance
// against the residual's, from the residual's band-3 SH. MIS weighs each against BSDF sampling with its
// pdf times the probability of its choice.
#include <memory>
#include <optional>

#include "engine/core/frame.hpp"
#include "engine/core/point2.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/scene_desc.hpp"
#include "engine/sh/sh_irradiance_form.hpp"
#include "engine/sun/sun.hpp"

namespace lp::render {

class SunLight {
 public:
  // Rotated and scaled as `env` rotates and scales the map; `residual` is the map without the sun.
  SunLight(const Sun& sun, const EnvLight& env, const EnvMap& residual);

  LightSample sample(Point2 u) const;
  float pdf() const { return pdf_; }  // solid angle, inside the cone
  // The probability that a light sample at a surface of (world) normal n goes to the sun, never below
  // kLeastChoice for either the sun or the residual map.
  float selection(Vec3 n) const;
  bool contains(Vec3 world_direction) const;
  Rgb radiance() const { return radiance_; }  // inside the cone

 private:
  Frame frame_;          // about the sun's direction
  float one_minus_cos_;  // 1 - cos r
  float chord_squared_;  // |d - axis|^2 at the cone's edge: 2 (1 - cos r)
  float pdf_;
  Vec3 map_x_, map_y_;               // the map's x and y axes in the world (it turns about z)
  float sun_irradiance_;             // luminance, facing the sun
  float residual_scale_;             // the map's intensity
  ShIrradianceForm residual_light_;  // luminance, in the map's frame
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
