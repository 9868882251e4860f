#include "engine/bsdf/bsdf_metallic_roughness.hpp"

#include <algorithm>
#include <cmath>

namespace lp::render {
namespace {

Rgb schlick(Rgb f0, float cos_i) {
  const float m = std::clamp(1.0f - cos_i, 0.0f, 1.0f);
  const float m5 = (m * m) * (m * m) * m;
  return f0 + (Rgb{1, 1, 1} - f0) * m5;
}

// 2 * integral of schlick(f0, mu) mu dmu = f0 + (1 - f0) * 2 B(2, 6) = f0 + (1 - f0) / 21.
Rgb schlick_average(Rgb f0) {
  return f0 + (Rgb{1, 1, 1} - f0) * (1.0f / 21.0f);
}

}  // namespace

float model_alpha(float roughness) {
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  return r * r;
}

bool model_mirror(float roughness) {
  return model_alpha(roughness) < kDeltaLobeAlpha;
}

const DielectricCoat& model_coat() {
  static const DielectricCoat coat(kModelDielectricIor);
  return coat;
}

MetallicRoughnessBsdf::MetallicRoughnessBsdf(Rgb base_color, float metallic, float roughness)
    : base_(base_color),
      metallic_(std::clamp(metallic, 0.0f, 1.0f)),
      metal_mirror_(model_mirror(roughness)),
      metal_(metal_mirror_ ? 0.0f : model_alpha(roughness)),
      metal_ms_fresnel_(metal_mirror_ ? Rgb{} : metal_.multiscatter_fresnel(schlick_average(base_color))),
      dielectric_(base_color, model_alpha(roughness), model_coat()) {}

Rgb MetallicRoughnessBsdf::eval_metal(Vec3 wo, Vec3 wi) const {
  if (metal_mirror_) return {};
  return metal_.eval(
      wo, wi, [this](float cos_d) { return schlick(base_, cos_d); }, metal_ms_fresnel_);
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
  if (metallic_ > 0 && !metal_mirror_) p += metal_.pdf(wo, wi) * metallic_;
  return p;
}

std::optional<BsdfSample> MetallicRoughnessBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  std::optional<Vec3> wi;
  if (u_lobe < metallic_) {
    if (metal_mirror_) return BsdfSample{{-wo.x, -wo.y, wo.z}, schlick(base_, wo.z), metallic_, 1.0f, true};
    wi = metal_.sample(wo, u_lobe / metallic_, u);
  } else {
    std::optional<BsdfSample> s = dielectric_.sample(wo, (u_lobe - metallic_) / (1.0f - metallic_), u);
    if (s && s->delta) {
      s->pdf *= 1.0f - metallic_;
      return s;
    }
    if (s) wi = s->wi;
  }
  if (!wi) return std::nullopt;
  return weighted_sample(*this, wo, *wi);
}

}  // namespace lp::render
