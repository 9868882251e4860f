#include "engine/render/env_light.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/render/warp.hpp"

namespace lp::render {

EnvLight::EnvLight(std::shared_ptr<const EnvMap> map, const Lighting& lighting)
    : map_(std::move(map)), intensity_(lighting.intensity) {
  if (!map_) throw Error(ErrorKind::InvalidArgument, "lighting: no environment map");
  if (!(std::isfinite(lighting.intensity) && lighting.intensity >= 0))
    throw Error(ErrorKind::InvalidArgument, "lighting: intensity must be finite and >= 0");
  if (!std::isfinite(lighting.rotation_deg))
    throw Error(ErrorKind::InvalidArgument, "lighting: rotation_deg must be finite");
  const double a = double(lighting.rotation_deg) * kPi / 180.0;
  cos_ = float(std::cos(a));
  sin_ = float(std::sin(a));
  // A black map lights nothing; it has no distribution to sample (sample_importance then gives pdf 0).
  dark_ = max_component(map_->power()) <= 0;
  if (lighting.mode == LightingMode::EnvMap && !dark_) importance_ = map_->sampler(kImportanceLuminance);
}

Rgb EnvLight::radiance(Vec3 world_direction) const {
  return map_->radiance(to_map(world_direction)) * intensity_;
}

LightSample EnvLight::sample_importance(Point2 u) const {
  if (!importance_) return {};
  const EnvSample s = importance_->sample(u.x, u.y);
  return {to_world(s.direction), s.radiance * intensity_, s.pdf};
}

EnvPixel EnvLight::locate(Vec3 world_direction) const {
  const Vec3 d = to_map(world_direction);
  const latlong::Uv uv = latlong::uv(d);
  // sin(theta) = hypot(x, y) / |d|, the same value as sin(uv.v * pi) without another sine.
  const float sin_theta = std::sqrt(d.x * d.x + d.y * d.y) / length(d);
  const EnvPixel p{latlong::pixel_x(uv.u, map_->width()), latlong::pixel_y(uv.v, map_->height()), sin_theta};
  if (importance_)
    importance_->prefetch(p.x, p.y);
  else
    __builtin_prefetch(map_->image().row(p.y) + 3 * p.x);
  return p;
}

LightSample EnvLight::sample_uniform(Point2 u) const {
  const Vec3 d = square_to_uniform_sphere(u.x, u.y);
  return {d, radiance(d), kUniformSpherePdf};
}

}  // namespace lp::render
