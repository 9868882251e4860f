#include "engine/bsdf/bsdf_gltf_pbr.hpp"

#include <algorithm>
#include <cmath>

namespace lp::render {
namespace {

// The base keeps at least this share of the samples (against layers that reflect much at wo).
inline constexpr float kMinBaseEstimate = 0.25f;

}  // namespace

bool GltfPbrParams::core_base() const {
  return base.ior == kModelDielectricIor && base.specular == 1 && base.specular_color == Rgb{1, 1, 1} &&
         base.transmission == 0;
}

GltfPbrBsdf::GltfPbrBsdf(const GltfPbrParams& p)
    : clearcoat_(p.clearcoat),
      clearcoat_roughness_(p.clearcoat_roughness),
      base_estimate_(std::max(kMinBaseEstimate,
                              (p.base.base_color.x + p.base.base_color.y + p.base.base_color.z) / 3.0f)) {
  if (p.core_base())
    core_.emplace(p.base.base_color, p.base.metallic, p.base.roughness);
  else
    extended_.emplace(p.base);
  set_clearcoat_normal(p.clearcoat_normal);
  if (max_component(p.sheen_color) > 0) sheen_.emplace(p.sheen_color, p.sheen_roughness);
}

void GltfPbrBsdf::set_clearcoat_normal(Vec3 normal) {
  if (clearcoat_ > 0) coat_.emplace(clearcoat_, clearcoat_roughness_, normal.z > 0 ? normal : Vec3{0, 0, 1});
}

const Bsdf& GltfPbrBsdf::base() const {
  return core_ ? static_cast<const Bsdf&>(*core_) : *extended_;
}

GltfPbrBsdf::Choice GltfPbrBsdf::choice(Vec3 wo) const {
  const float coat = coat_ ? coat_->albedo(wo) : 0.0f;
  const float sheen = sheen_ ? (1.0f - coat) * sheen_->strength() * sheen_->albedo(wo.z) : 0.0f;
  const float rest = (1.0f - coat) * (sheen_ ? 1.0f - sheen_->strength() * sheen_->albedo(wo.z) : 1.0f);
  const float base = rest * base_estimate_;
  const float total = coat + sheen + base;
  return {coat / total, sheen / total, base / total};
}

float GltfPbrBsdf::layer_scale(Vec3 wo, Vec3 wi) const {
  float s = 1;
  if (coat_) s *= std::min(1.0f - coat_->albedo(wo), 1.0f - coat_->albedo(wi));
  if (sheen_) {
    const float k = sheen_->strength();
    s *= std::min(1.0f - k * sheen_->albedo(wo.z), 1.0f - k * sheen_->albedo(std::abs(wi.z)));
  }
  return s;
}

Rgb GltfPbrBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0) return base().eval(wo, wi);
  Rgb f = base().eval(wo, wi) * layer_scale(wo, wi);
  if (sheen_)
    f += sheen_->eval(wo, wi) * (coat_ ? std::min(1.0f - coat_->albedo(wo), 1.0f - coat_->albedo(wi)) : 1.0f);
  if (coat_) f += coat_->eval(wo, wi);
  return f;
}

float GltfPbrBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0) return base().pdf(wo, wi);
  const Choice c = choice(wo);
  float p = c.base * base().pdf(wo, wi);
  if (sheen_) p += c.sheen * SheenLobe::pdf(wi);
  if (coat_) p += c.coat * coat_->pdf(wo, wi);
  return p;
}

std::optional<BsdfSample> GltfPbrBsdf::weighted(Vec3 wo, Vec3 wi) const {
  if (wi.z == 0) return std::nullopt;
  const float p = pdf(wo, wi);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi) / p, p};
}

std::optional<BsdfSample> GltfPbrBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return base().sample(wo, u_lobe, u);
  const Choice c = choice(wo);
  if (u_lobe < c.coat) {
    const std::optional<Vec3> wi = coat_->sample(wo, u);
    if (!wi) return std::nullopt;
    if (!coat_->mirror()) return weighted(wo, *wi);
    if (wi->z <= 0) return std::nullopt;
    const float f = coat_->albedo(wo) / c.coat;
    return BsdfSample{*wi, {f, f, f}, c.coat, 1.0f, true};
  }
  if (u_lobe < c.coat + c.sheen) return weighted(wo, SheenLobe::sample(u));
  const float v = std::clamp((u_lobe - c.coat - c.sheen) / c.base, 0.0f, 0.99999994f);
  std::optional<BsdfSample> s = base().sample(wo, v, u);
  if (!s) return std::nullopt;
  if (!s->delta) {
    std::optional<BsdfSample> w = weighted(wo, s->wi);
    if (w) w->eta = s->eta;  // a refraction into the volume
    return w;
  }
  s->weight = s->weight * (layer_scale(wo, s->wi) / c.base);
  s->pdf *= c.base;
  return s;
}

}  // namespace lp::render
