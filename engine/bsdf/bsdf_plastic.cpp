#include "engine/bsdf/bsdf_plastic.hpp"

#include <utility>

#include "engine/core/constants.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

GgxAlbedo::Fresnel dielectric_fresnel(float ior) {
  return [ior](double cos_i) { return fresnel_dielectric(cos_i, 1.0, ior); };
}

float mean_fresnel(float ior) {
  return float(cosine_weighted_mean(dielectric_fresnel(ior)));
}

// The coat's alpha: 0 (a mirror) below kDeltaLobeAlpha.
float coat_alpha(float roughness) {
  return roughness < kDeltaLobeAlpha ? 0.0f : roughness;
}

}  // namespace

DielectricCoat::DielectricCoat(float index)
    : ior(index), fresnel_average(mean_fresnel(index)), single_scattering(dielectric_fresnel(index)) {}

DielectricCoat::DielectricCoat(float index, float alpha)
    : ior(index), fresnel_average(mean_fresnel(index)), single_scattering(dielectric_fresnel(index), alpha) {}

PlasticBsdf::PlasticBsdf(Rgb albedo, float ior, float roughness)
    : PlasticBsdf(albedo, roughness, std::make_shared<const DielectricCoat>(ior, coat_alpha(roughness)),
                  nullptr) {}

PlasticBsdf::PlasticBsdf(Rgb albedo, float roughness, const DielectricCoat& coat)
    : PlasticBsdf(albedo, roughness, nullptr, &coat) {}

PlasticBsdf::PlasticBsdf(Rgb albedo, float roughness, std::shared_ptr<const DielectricCoat> owned,
                         const DielectricCoat* coat)
    : albedo_(albedo),
      delta_specular_(roughness < kDeltaLobeAlpha),
      owned_coat_(std::move(owned)),
      coat_(coat ? coat : owned_coat_.get()),
      lobe_(roughness),
      single_scattering_(coat_->single_scattering.row(roughness)),
      ms_fresnel_(lobe_.multiscatter_fresnel(coat_->fresnel_average)),
      coat_average_(delta_specular_
                        ? coat_->fresnel_average
                        : single_scattering_.average() + ms_fresnel_ * lobe_.multiscatter_average()),
      mean_albedo_((albedo.x + albedo.y + albedo.z) / 3.0f) {}

float PlasticBsdf::fresnel(float cos_i) const {
  return float(fresnel_dielectric(cos_i, 1.0, coat_->ior));
}

float PlasticBsdf::coat_albedo(float cos_o) const {
  if (delta_specular_) return fresnel(cos_o);
  return single_scattering_(cos_o) + ms_fresnel_ * lobe_.multiscatter_albedo(cos_o);
}

// The coat's single-scattering lobe (what visible-normal sampling covers) against the rest.
float PlasticBsdf::specular_probability(float cos_o) const {
  const float coat = coat_albedo(cos_o);
  const float specular = delta_specular_ ? coat : single_scattering_(cos_o);
  const float total = coat + (1.0f - coat) * mean_albedo_;
  return total > 0 ? specular / total : 1.0f;
}

Rgb PlasticBsdf::eval_specular(Vec3 wo, Vec3 wi) const {
  const auto fresnel_rgb = [this](float cos_d) {
    const float f = fresnel(cos_d);
    return Rgb{f, f, f};
  };
  return lobe_.eval(wo, wi, fresnel_rgb, Rgb{ms_fresnel_, ms_fresnel_, ms_fresnel_});
}

Rgb PlasticBsdf::eval_diffuse(Vec3 wo, Vec3 wi) const {
  const float t = (1.0f - coat_albedo(wo.z)) * (1.0f - coat_albedo(wi.z)) / (kPiF * (1.0f - coat_average_));
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
  const float ps = specular_probability(wo.z);
  float p = (1.0f - ps) * cosine_hemisphere_pdf(wi.z);
  if (!delta_specular_) p += ps * lobe_.ggx().reflection_pdf(wo, normalize(wo + wi));
  return p;
}

std::optional<BsdfSample> PlasticBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  const float ps = specular_probability(wo.z);
  if (u_lobe >= ps) return weighted_sample(*this, wo, square_to_cosine_hemisphere(u.x, u.y));
  if (delta_specular_) {
    const float f = fresnel(wo.z);
    return BsdfSample{{-wo.x, -wo.y, wo.z}, Rgb{f, f, f} / ps, ps, 1.0f, true};
  }
  const std::optional<Vec3> wi = lobe_.ggx().sample_reflection(wo, u.x, u.y);
  if (!wi) return std::nullopt;
  return weighted_sample(*this, wo, *wi);
}

}  // namespace lp::render
