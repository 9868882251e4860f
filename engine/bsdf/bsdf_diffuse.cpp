#include "engine/bsdf/bsdf_diffuse.hpp"

#include "engine/core/constants.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {

Rgb DiffuseBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  return albedo_ * (wi.z / kPiF);
}

float DiffuseBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return cosine_hemisphere_pdf(wi.z);
}

std::optional<BsdfSample> DiffuseBsdf::sample(Vec3 wo, float, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  const Vec3 wi = square_to_cosine_hemisphere(u.x, u.y);
  if (wi.z <= 0) return std::nullopt;
  return BsdfSample{wi, albedo_, cosine_hemisphere_pdf(wi.z)};
}

}  // namespace lp::render
