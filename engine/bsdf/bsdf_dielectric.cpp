#include "engine/bsdf/bsdf_dielectric.hpp"

#include <cmath>

#include "engine/fresnel/dielectric.hpp"

namespace lp::render {

std::optional<BsdfSample> DielectricBsdf::sample(Vec3 wo, float u_lobe, Point2) const {
  if (wo.z == 0) return std::nullopt;
  const bool entering = wo.z > 0;
  const double eta_i = entering ? 1.0 : double(ior_), eta_t = entering ? double(ior_) : 1.0;
  const double cos_i = std::abs(double(wo.z));
  const auto fresnel = fresnel_dielectric_polarized(cos_i, eta_i, eta_t);
  const float reflectance = float(fresnel.reflectance());
  if (u_lobe < reflectance || fresnel.total_internal_reflection) {
    const float p = fresnel.total_internal_reflection ? 1.0f : reflectance;
    return BsdfSample{{-wo.x, -wo.y, wo.z}, {1, 1, 1}, p, 1.0f, true};
  }
  const float eta = float(eta_t / eta_i);
  const float side = entering ? 1.0f : -1.0f;
  const float cos_t = float(fresnel.cos_t);
  const Vec3 wi = normalize(Vec3{-wo.x / eta, -wo.y / eta, -side * cos_t});
  const float scale = 1.0f / (eta * eta);
  return BsdfSample{wi, {scale, scale, scale}, 1.0f - reflectance, eta, true};
}

}  // namespace lp::render
