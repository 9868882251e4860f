#include "engine/bsdf/bsdf_conductor.hpp"

#include "engine/fresnel/conductor.hpp"

namespace lp::render {
namespace {

Rgb fresnel_average(Rgb eta, Rgb k) {
  const auto mean = [](float e, float kk) {
    return float(cosine_weighted_mean([=](double mu) { return fresnel_conductor(mu, e, kk); }));
  };
  return {mean(eta.x, k.x), mean(eta.y, k.y), mean(eta.z, k.z)};
}

}  // namespace

ConductorBsdf::ConductorBsdf(Rgb eta, Rgb k, float roughness)
    : eta_(eta),
      k_(k),
      delta_specular_(roughness < kDeltaLobeAlpha),
      lobe_(roughness),
      ms_fresnel_(delta_specular_ ? Rgb{} : lobe_.multiscatter_fresnel(fresnel_average(eta, k))) {}

Rgb ConductorBsdf::fresnel(float cos_i) const {
  return fresnel_conductor(cos_i, eta_, k_);
}

Rgb ConductorBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (delta_specular_ || wo.z <= 0 || wi.z <= 0) return {};
  return lobe_.eval(
      wo, wi, [this](float cos_d) { return fresnel(cos_d); }, ms_fresnel_);
}

float ConductorBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (delta_specular_ || wo.z <= 0 || wi.z <= 0) return 0;
  return lobe_.pdf(wo, wi);
}

std::optional<BsdfSample> ConductorBsdf::sample(Vec3 wo, float u_lobe, Point2 u) const {
  if (wo.z <= 0) return std::nullopt;
  if (delta_specular_) return BsdfSample{{-wo.x, -wo.y, wo.z}, fresnel(wo.z), 1.0f, 1.0f, true};
  const std::optional<Vec3> wi = lobe_.sample(wo, u_lobe, u);
  if (!wi) return std::nullopt;
  return weighted_sample(*this, wo, *wi);
}

}  // namespace lp::render
