#pragma once
// A metal: complex index eta + i k per RGB channel (engine/fresnel), smooth (a delta lobe) when the
// roughness is 0, otherwise GGX microfacet reflection with visible-normal sampling and the energy its
// single scattering loses given back (microfacet_multiscatter.hpp), with F_avg the cosine-weighted mean
// of the metal's Fresnel reflectance.
#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/microfacet_multiscatter.hpp"

namespace lp::render {

class ConductorBsdf final : public Bsdf {
 public:
  ConductorBsdf(Rgb eta, Rgb k, float roughness);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return !delta_specular_; }

 private:
  Rgb fresnel(float cos_i) const;

  Rgb eta_, k_;
  bool delta_specular_;  // roughness below kDeltaLobeAlpha: the specular lobe is a mirror (delta)
  CompensatedGgx lobe_;
  Rgb ms_fresnel_;  // F_ms
};

}  // namespace lp::render
