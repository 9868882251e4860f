#include "engine/render/sun_light.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/fast_sincos.hpp"
#include "engine/sh/sh_projection.hpp"
#include "engine/sun/sun_extraction.hpp"

namespace lp::render {
namespace {

inline constexpr float kLeastChoice = 0.05f;

}  // namespace

SunLight::SunLight(const Sun& sun, const EnvLight& env, const EnvMap& residual)
    : frame_(Frame::from_normal(normalize(env.to_world(sun.direction)))),
      map_x_(env.to_world({1, 0, 0})),
      map_y_(env.to_world({0, 1, 0})),
      sun_irradiance_(float((sun.irradiance[0] + sun.irradiance[1] + sun.irradiance[2]) / 3) *
                      env.intensity()),
      residual_light_(sh_irradiance(sh_projection_cached(residual)->radiance.truncated(3))) {
  const double s = std::sin(sun.angular_radius / 2), one_minus_cos = 2 * s * s;
  const double solid_angle = cone_solid_angle(sun.angular_radius);
  one_minus_cos_ = float(one_minus_cos);
  chord_squared_ = float(2 * one_minus_cos);
  pdf_ = float(1 / solid_angle);
  residual_scale_ = env.intensity();
  const auto channel = [&](int c) { return float(sun.power[size_t(c)] / solid_angle) * env.intensity(); };
  radiance_ = {channel(0), channel(1), channel(2)};
}

LightSample SunLight::sample(Point2 u) const {
  // cos theta = 1 - u (1 - cos r); sin theta from the same product, exact where cos theta rounds to 1.
  const float a = u.x * one_minus_cos_;
  const float sin_theta = std::sqrt(std::max(0.0f, a * (2 - a)));
  const SinCos phi = sincos_turns(u.y);
  const Vec3 local{sin_theta * phi.cos, sin_theta * phi.sin, 1 - a};
  return {normalize(frame_.to_world(local)), radiance_, pdf_};
}

float SunLight::selection(Vec3 n) const {
  const float from_sun = sun_irradiance_ * std::max(0.0f, dot(n, frame_.n));
  const Vec3 m{dot(n, map_x_), dot(n, map_y_), n.z};
  const float from_residual = residual_scale_ * std::max(0.0f, residual_light_(m));
  const float total = from_sun + from_residual;
  return total > 0 ? std::clamp(from_sun / total, kLeastChoice, 1 - kLeastChoice) : 0.5f;
}

bool SunLight::contains(Vec3 d) const {
  const Vec3 chord = d - frame_.n;
  return dot(chord, chord) <= chord_squared_;
}

SunSplit split_sun(std::shared_ptr<const EnvMap> map, const Lighting& lighting) {
  if (lighting.sun == SunMode::None || !map) return {std::move(map), std::nullopt};
  SunExtraction extraction = extract_sun(*map, lighting.sun_parameters);
  if (!extraction.sun) return {std::move(map), std::nullopt};
  return {std::move(extraction.residual), extraction.sun};
}

}  // namespace lp::render
