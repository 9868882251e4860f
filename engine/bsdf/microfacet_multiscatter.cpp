#include "engine/bsdf/microfacet_multiscatter.hpp"

#include "engine/core/constants.hpp"
#include "engine/sampling/warp.hpp"

namespace lp::render {
namespace {

// Below this 1 - E_avg (alpha ~ 1e-3) the lobe loses nothing measurable, and f_ms would divide by ~0.
constexpr float kMinLostEnergy = 1e-6f;

float lost_energy_scale(float average_albedo) {
  const float lost = 1.0f - average_albedo;
  return lost > kMinLostEnergy ? 1.0f / (kPiF * lost) : 0.0f;
}

}  // namespace

CompensatedGgx::CompensatedGgx(float alpha)
    : ggx_(alpha), albedo_(ggx_albedo().row(alpha)), scale_(lost_energy_scale(albedo_.average())) {}

float CompensatedGgx::multiscatter_fresnel(float f_avg) const {
  const float e_avg = albedo_.average();
  return f_avg * f_avg * e_avg / (1.0f - f_avg * (1.0f - e_avg));
}

float CompensatedGgx::pdf(Vec3 wo, Vec3 wi) const {
  const float p = multiscatter_probability(wo.z);
  return (1.0f - p) * ggx_.reflection_pdf(wo, normalize(wo + wi)) + p * cosine_hemisphere_pdf(wi.z);
}

std::optional<Vec3> CompensatedGgx::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (u_lobe < multiscatter_probability(wo.z)) return square_to_cosine_hemisphere(u.x, u.y);
  return ggx_.sample_reflection(wo, u.x, u.y);
}

}  // namespace lp::render
