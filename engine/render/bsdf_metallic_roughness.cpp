#include "engine/render/bsdf_metallic_roughness.hpp"

#include <algorithm>
#include <cmath>

namespace lp::render {
namespace {

float model_alpha(float roughness) {
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  return std::max(r * r, kMinModelAlpha);
}

float coat_diffuse_fresnel() {
  static const float fdr = PlasticBsdf::diffuse_fresnel(kModelDielectricIor);
  return fdr;
}

Rgb schlick(Rgb f0, float cos_i) {
  const float m = std::clamp(1.0f - cos_i, 0.0f, 1.0f);
  const float m5 = (m * m) * (m * m) * m;
  return f0 + (Rgb{1, 1, 1} - f0) * m5;
}

}  // namespace

MetallicRoughnessBsdf::MetallicRoughnessBsdf(Rgb base_color, float metallic, float roughness)
    : base_(base_color),
      metallic_(std::clamp(metallic, 0.0f, 1.0f)),
      ggx_(model_alpha(roughness)),
      dielectric_(base_color, kModelDielectricIor, model_alpha(roughness), coat_diffuse_fresnel()) {}

Rgb MetallicRoughnessBsdf::eval_metal(Vec3 wo, Vec3 wi) const {
  const Vec3 h = normalize(wo + wi);
  return schlick(base_, dot(wo, h)) * ggx_.reflection(wo, wi, h);
}

float MetallicRoughnessBsdf::pdf_metal(Vec3 wo, Vec3 wi) const {
  const Vec3 h = normalize(wo + wi);
  return ggx_.reflection_pdf(wo, h);
}

Rgb MetallicRoughnessBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Rgb f{};
  if (metallic_ < 1) f += dielectric_.eval(wo, wi) * (1.0f - metallic_);
  if (metallic_ > 0) f += eval_metal(wo, wi) * metallic_;
  return f;
}

float MetallicRoughnessBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  float p = 0;
  if (metallic_ < 1) p += dielectric_.pdf(wo, wi) * (1.0f - metallic_);
  if (metallic_ > 0) p += pdf_metal(wo, wi) * metallic_;
  return p;
}

std::optional<BsdfSample> MetallicRoughnessBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  Vec3 wi;
  if (u_lobe < metallic_) {
    const Vec3 h = ggx_.sample_visible_normal(wo, u.x, u.y);
    if (dot(wo, h) <= 0) return std::nullopt;
    wi = reflect(wo, h);
  } else {
    const std::optional<BsdfSample> s = dielectric_.sample(wo, (u_lobe - metallic_) / (1.0f - metallic_), u);
    if (!s) return std::nullopt;
    wi = s->wi;
  }
  if (wi.z <= 0) return std::nullopt;
  const float p = pdf(wo, wi);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi) / p, p};
}

}  // namespace lp::render
