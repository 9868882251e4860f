#include "engine/bsdf/bsdf_gltf_base.hpp"

#include <algorithm>
#include <cmath>

#include "engine/bsdf/bsdf_dielectric.hpp"
#include "engine/core/constants.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

// E_F of the GGX lobe for F = (1 - c)^5, Schlick's grazing term (computed at first use).
const GgxAlbedo& schlick_tail_albedo() {
  static const GgxAlbedo table([](double c) {
    const double m = std::clamp(1.0 - c, 0.0, 1.0);
    return (m * m) * (m * m) * m;
  });
  return table;
}

Rgb dielectric_f0(float ior, Rgb specular_color, float specular) {
  const float r = (ior - 1.0f) / (ior + 1.0f);
  const Rgb f0 = specular_color * (r * r);
  return Rgb{std::min(f0.x, 1.0f), std::min(f0.y, 1.0f), std::min(f0.z, 1.0f)} * specular;
}

float mean(Rgb c) {
  return (c.x + c.y + c.z) / 3.0f;
}

Vec3 mirror_through_surface(Vec3 w) {
  return {w.x, w.y, -w.z};
}

}  // namespace

GltfBaseBsdf::GltfBaseBsdf(const GltfBaseParams& p)
    : base_(p.base_color),
      metallic_(std::clamp(p.metallic, 0.0f, 1.0f)),
      ior_(p.ior),
      transmission_(std::clamp(p.transmission, 0.0f, 1.0f)),
      thin_walled_(p.thin_walled),
      mirror_(model_mirror(p.roughness)),
      f0_(dielectric_f0(p.ior, p.specular_color, std::clamp(p.specular, 0.0f, 1.0f))),
      f90_(std::clamp(p.specular, 0.0f, 1.0f)),
      max_channel_(f0_.x >= f0_.y && f0_.x >= f0_.z ? 0 : (f0_.y >= f0_.z ? 1 : 2)),
      lobe_(mirror_ ? 0.0f : model_alpha(p.roughness)),
      e1_(ggx_albedo().row(lobe_.ggx().alpha())),
      e5_(schlick_tail_albedo().row(lobe_.ggx().alpha())),
      ms_fresnel_(lobe_.multiscatter_fresnel(f0_ + (Rgb{f90_, f90_, f90_} - f0_) * (1.0f / 21.0f))),
      specular_average_(mean_specular_albedo()),
      metal_(p.base_color, 1.0f, p.roughness) {
  if (!thin_walled_ && !mirror_ && transmission_ > 0 && ior_ != 1)
    interface_.emplace(ior_, model_alpha(p.roughness));
}

float GltfBaseBsdf::specular_albedo(float cos_o) const {
  const int c = max_channel_;
  if (mirror_) return schlick(cos_o)[c];
  return f0_[c] * (e1_(cos_o) - e5_(cos_o)) + f90_ * e5_(cos_o) +
         ms_fresnel_[c] * lobe_.multiscatter_albedo(cos_o);
}

// 2 * integral of specular_albedo(mu) mu dmu; for a mirror, that of Schlick's F: the (1 - mu)^5 term
// averages to 2 B(2, 6) = 1 / 21.
float GltfBaseBsdf::mean_specular_albedo() const {
  const int c = max_channel_;
  if (mirror_) return f0_[c] + (f90_ - f0_[c]) / 21.0f;
  return f0_[c] * (e1_.average() - e5_.average()) + f90_ * e5_.average() +
         ms_fresnel_[c] * lobe_.multiscatter_average();
}

GltfBaseBsdf::Choice GltfBaseBsdf::choice(float cos_o) const {
  const float rest = 1.0f - metallic_;
  const float es = specular_albedo(cos_o);
  const float d = (1.0f - es) * (1.0f - transmission_) * mean(base_);
  const float t = (1.0f - es) * transmission_ * mean(base_);
  const float total = es + d + t;
  if (!(total > 0)) return {metallic_, rest, 0, 0};
  return {metallic_, rest * es / total, rest * d / total, rest * t / total};
}

Rgb GltfBaseBsdf::schlick(float cos_d) const {
  const float m = std::clamp(1.0f - cos_d, 0.0f, 1.0f);
  const float m5 = (m * m) * (m * m) * m;
  return f0_ + (Rgb{f90_, f90_, f90_} - f0_) * m5;
}

Rgb GltfBaseBsdf::eval_specular(Vec3 wo, Vec3 wi) const {
  if (mirror_) return {};
  return lobe_.eval(
      wo, wi, [this](float cos_d) { return schlick(cos_d); }, ms_fresnel_);
}

Rgb GltfBaseBsdf::eval_diffuse(Vec3 wo, Vec3 wi) const {
  const float t =
      (1.0f - specular_albedo(wo.z)) * (1.0f - specular_albedo(wi.z)) / (kPiF * (1.0f - specular_average_));
  return base_ * ((1.0f - transmission_) * t * wi.z);
}

Rgb GltfBaseBsdf::transmission_tint(float cos_o) const {
  return base_ * (transmission_ * (1.0f - specular_albedo(cos_o)) * (1.0f - metallic_));
}

// The rough transmission lobes (the smooth ones are delta): wo above, wi below the surface.
Rgb GltfBaseBsdf::eval_transmission(Vec3 wo, Vec3 wi) const {
  if (interface_) return transmission_tint(wo.z) * (interface_->refraction_pdf(wo, wi) / (ior_ * ior_));
  if (!thin_walled_ || mirror_) return {};
  const auto white = [](float) { return Rgb{1, 1, 1}; };
  return transmission_tint(wo.z) * lobe_.eval(wo, mirror_through_surface(wi), white, Rgb{1, 1, 1});
}

float GltfBaseBsdf::transmission_pdf(Vec3 wo, Vec3 wi) const {
  if (interface_) return interface_->refraction_pdf(wo, wi);
  if (!thin_walled_ || mirror_) return 0;
  return lobe_.pdf(wo, mirror_through_surface(wi));
}

Rgb GltfBaseBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z < 0 && interface_) return interface_->eval(wo, wi);
  if (wo.z <= 0 || wi.z == 0) return {};
  if (wi.z < 0) return transmission_ > 0 ? eval_transmission(wo, wi) : Rgb{};
  const float rest = 1.0f - metallic_;
  Rgb f{};
  if (metallic_ > 0) f += metal_.eval(wo, wi) * metallic_;
  if (rest > 0) f += (eval_specular(wo, wi) + eval_diffuse(wo, wi)) * rest;
  return f;
}

float GltfBaseBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z < 0 && interface_) return interface_->pdf(wo, wi);
  if (wo.z <= 0 || wi.z == 0) return 0;
  const Choice c = choice(wo.z);
  if (wi.z < 0) return c.transmission > 0 ? c.transmission * transmission_pdf(wo, wi) : 0;
  float p = c.diffuse * cosine_hemisphere_pdf(wi.z);
  if (!mirror_) p += c.specular * lobe_.pdf(wo, wi);
  if (metallic_ > 0) p += c.metal * metal_.pdf(wo, wi);
  return p;
}

BsdfSample GltfBaseBsdf::weighted(Vec3 wo, Vec3 wi) const {
  const float p = pdf(wo, wi);
  if (!(p > 0)) return {wi, {}, 0};
  return {wi, eval(wo, wi) / p, p};
}

// The delta transmissions: straight on through a smooth thin wall, refracted into a thick one.
std::optional<BsdfSample> GltfBaseBsdf::sample_transmission(Vec3 wo, float probability) const {
  const Rgb tint = transmission_tint(wo.z);
  if (thin_walled_) return BsdfSample{-wo, tint / probability, probability, 1.0f, true};
  const std::optional<double> cos_t = transmitted_cos(wo.z, 1.0, ior_);
  if (!cos_t) return std::nullopt;
  const float eta = ior_;
  const Vec3 wi = normalize(Vec3{-wo.x / eta, -wo.y / eta, -float(*cos_t)});
  return BsdfSample{wi, tint / (probability * eta * eta), probability, eta, true};
}

std::optional<BsdfSample> GltfBaseBsdf::sample_from_inside(Vec3 wo, float u_lobe, Point2 u) const {
  if (interface_) return interface_->sample(wo, u_lobe, u);
  return DielectricBsdf(ior_).sample(wo, u_lobe, {});
}

std::optional<BsdfSample> GltfBaseBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z < 0 && !two_sided()) return sample_from_inside(wo, u_lobe, u);
  if (wo.z <= 0) return std::nullopt;
  const Choice c = choice(wo.z);
  std::optional<Vec3> wi;
  if (u_lobe < c.metal) {
    std::optional<BsdfSample> s = metal_.sample(wo, u_lobe / c.metal, u);
    if (s && s->delta) {  // the metal's mirror, chosen with probability c.metal
      s->weight = s->weight * (metallic_ / c.metal);
      s->pdf *= c.metal;
      return s;
    }
    if (s) wi = s->wi;
  } else if (u_lobe - c.metal < c.specular) {
    if (mirror_)
      return BsdfSample{
          {-wo.x, -wo.y, wo.z}, schlick(wo.z) * ((1.0f - metallic_) / c.specular), c.specular, 1.0f, true};
    wi = lobe_.sample(wo, (u_lobe - c.metal) / c.specular, u);
  } else if (u_lobe - c.metal < c.specular + c.diffuse) {
    wi = square_to_cosine_hemisphere(u.x, u.y);
  } else {
    if (!(c.transmission > 0)) return std::nullopt;
    if (interface_) {
      wi = interface_->sample_refraction(wo, u);
    } else if (thin_walled_ && !mirror_) {
      const float v = (u_lobe - c.metal - c.specular - c.diffuse) / c.transmission;
      const std::optional<Vec3> m = lobe_.sample(wo, std::clamp(v, 0.0f, 0.99999994f), u);
      if (m) wi = mirror_through_surface(*m);
    } else {
      return sample_transmission(wo, c.transmission);
    }
  }
  if (!wi || wi->z == 0) return std::nullopt;
  BsdfSample s = weighted(wo, *wi);
  if (!(s.pdf > 0)) return std::nullopt;
  if (interface_ && wi->z < 0) s.eta = ior_;
  return s;
}

}  // namespace lp::render
