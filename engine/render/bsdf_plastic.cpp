#include "engine/render/bsdf_plastic.hpp"

#include <algorithm>

#include "engine/core/constants.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/render/warp.hpp"

namespace lp::render {
namespace {

double diffuse_fresnel_reflectance(double ior) {
  constexpr int kSteps = 4096;  // midpoint rule; F is smooth in mu, the error is ~1e-7
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    sum += fresnel_dielectric(mu, 1.0, ior) * mu;
  }
  return 2.0 * sum / kSteps;
}

}  // namespace

float PlasticBsdf::diffuse_fresnel(float ior) {
  return float(diffuse_fresnel_reflectance(ior));
}

PlasticBsdf::PlasticBsdf(Rgb albedo, float ior, float roughness)
    : PlasticBsdf(albedo, ior, roughness, diffuse_fresnel(ior)) {}

PlasticBsdf::PlasticBsdf(Rgb albedo, float ior, float roughness, float fdr)
    : albedo_(albedo),
      ior_(ior),
      delta_specular_(roughness < kDeltaLobeAlpha),
      ggx_(roughness),
      fdr_(fdr),
      mean_albedo_((albedo.x + albedo.y + albedo.z) / 3.0f) {}

float PlasticBsdf::fresnel(float cos_i) const {
  return float(fresnel_dielectric(cos_i, 1.0, ior_));
}

// Choose the coat in proportion to its reflectance against the base's (1 - F) * albedo.
float PlasticBsdf::specular_probability(float fresnel_o) const {
  const float diffuse = (1.0f - fresnel_o) * mean_albedo_;
  return fresnel_o + diffuse > 0 ? fresnel_o / (fresnel_o + diffuse) : 1.0f;
}

Rgb PlasticBsdf::eval_specular(Vec3 wo, Vec3 wi) const {
  const Vec3 h = normalize(wo + wi);
  const float f = fresnel(dot(wo, h)) * ggx_.reflection(wo, wi, h);
  return {f, f, f};
}

float PlasticBsdf::pdf_specular(Vec3 wo, Vec3 wi) const {
  const Vec3 h = normalize(wo + wi);
  return ggx_.reflection_pdf(wo, h);
}

Rgb PlasticBsdf::eval_diffuse(Vec3 wo, Vec3 wi) const {
  const float t = (1.0f - fresnel(wo.z)) * (1.0f - fresnel(wi.z)) / (kPiF * (1.0f - fdr_));
  return albedo_ * (t * wi.z);
}

Rgb PlasticBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Rgb f = eval_diffuse(wo, wi);
  if (!delta_specular_) f += eval_specular(wo, wi);
  return f;
}

float PlasticBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  const float ps = specular_probability(fresnel(wo.z));
  float p = (1.0f - ps) * cosine_hemisphere_pdf(wi.z);
  if (!delta_specular_) p += ps * pdf_specular(wo, wi);
  return p;
}

std::optional<BsdfSample> PlasticBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  const float fo = fresnel(wo.z);
  const float ps = specular_probability(fo);
  Vec3 wi;
  if (u_lobe < ps) {
    if (delta_specular_) return BsdfSample{{-wo.x, -wo.y, wo.z}, Rgb{fo, fo, fo} / ps, ps, 1.0f, true};
    const Vec3 h = ggx_.sample_visible_normal(wo, u.x, u.y);
    if (dot(wo, h) <= 0) return std::nullopt;
    wi = reflect(wo, h);
  } else {
    wi = square_to_cosine_hemisphere(u.x, u.y);
  }
  if (wi.z <= 0) return std::nullopt;
  const float p = pdf(wo, wi);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi) / p, p};
}

}  // namespace lp::render
