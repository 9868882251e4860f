#include "engine/bsdf/clearcoat_lobe.hpp"

#include <algorithm>
#include <cmath>

#include "engine/bsdf/bsdf_metallic_roughness.hpp"
#include "engine/fresnel/dielectric.hpp"

namespace lp::render {

ClearcoatLobe::ClearcoatLobe(float weight, float roughness, Vec3 normal)
    : weight_(std::clamp(weight, 0.0f, 1.0f)),
      mirror_(model_mirror(roughness)),
      ggx_(mirror_ ? 0.0f : model_alpha(roughness)),
      albedo_(model_coat().single_scattering.row(ggx_.alpha())),
      frame_(Frame::from_normal(normal)) {}

Rgb ClearcoatLobe::eval(Vec3 wo, Vec3 wi) const {
  if (mirror_) return {};
  const Vec3 o = frame_.to_local(wo), i = frame_.to_local(wi);
  if (o.z <= 0 || i.z <= 0) return {};
  const Vec3 h = normalize(o + i);
  const float f = float(fresnel_dielectric(dot(o, h), 1.0, kModelDielectricIor));
  const float v = weight_ * f * ggx_.reflection(o, i, h);
  return {v, v, v};
}

float ClearcoatLobe::pdf(Vec3 wo, Vec3 wi) const {
  if (mirror_) return 0;
  const Vec3 o = frame_.to_local(wo), i = frame_.to_local(wi);
  if (o.z <= 0 || i.z <= 0) return 0;
  return ggx_.reflection_pdf(o, normalize(o + i));
}

std::optional<Vec3> ClearcoatLobe::sample(Vec3 wo, Point2 u) const {
  const Vec3 o = frame_.to_local(wo);
  if (o.z <= 0) return std::nullopt;
  if (mirror_) return frame_.to_world({-o.x, -o.y, o.z});
  const std::optional<Vec3> i = ggx_.sample_reflection(o, u.x, u.y);
  if (!i) return std::nullopt;
  return frame_.to_world(*i);
}

float ClearcoatLobe::albedo(Vec3 w) const {
  const float mu = std::min(1.0f, std::abs(dot(w, frame_.n)));
  if (mirror_) return weight_ * float(fresnel_dielectric(mu, 1.0, kModelDielectricIor));
  return weight_ * albedo_(mu);
}

}  // namespace lp::render
