#include "engine/render/bsdf_conductor.hpp"

#include "engine/fresnel/conductor.hpp"

namespace lp::render {

ConductorBsdf::ConductorBsdf(Rgb eta, Rgb k, float roughness)
    : eta_(eta), k_(k), delta_specular_(roughness < kDeltaLobeAlpha), ggx_(roughness) {}

Rgb ConductorBsdf::fresnel(float cos_i) const {
  return fresnel_conductor(cos_i, eta_, k_);
}

Rgb ConductorBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (delta_specular_ || wo.z <= 0 || wi.z <= 0) return {};
  const Vec3 h = normalize(wo + wi);
  return fresnel(dot(wo, h)) * ggx_.reflection(wo, wi, h);
}

float ConductorBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (delta_specular_ || wo.z <= 0 || wi.z <= 0) return 0;
  const Vec3 h = normalize(wo + wi);
  return ggx_.reflection_pdf(wo, h);
}

std::optional<BsdfSample> ConductorBsdf::sample(Vec3 wo, float, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  if (delta_specular_) return BsdfSample{{-wo.x, -wo.y, wo.z}, fresnel(wo.z), 1.0f, 1.0f, true};
  const Vec3 h = ggx_.sample_visible_normal(wo, u.x, u.y);
  const float wo_h = dot(wo, h);
  if (wo_h <= 0) return std::nullopt;
  const Vec3 wi = reflect(wo, h);
  if (wi.z <= 0) return std::nullopt;
  const float p = ggx_.reflection_pdf(wo, h);
  if (!(p > 0)) return std::nullopt;
  const Rgb weight = fresnel(wo_h) * (ggx_.g(wo, wi) / ggx_.g1(wo));
  return BsdfSample{wi, weight, p};
}

}  // namespace lp::render
