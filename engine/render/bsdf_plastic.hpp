#pragma once
// A diffuse base under a dielectric coat (after Mitsuba's plastic / roughplastic): the coat reflects
// specularly (smooth, a delta lobe, or GGX when rough) with the dielectric Fresnel reflectance F; the
// light it transmits is scattered by the base and leaves through the coat again:
//   f_d = albedo (1 - F(cos_o)) (1 - F(cos_i)) / (pi (1 - Fdr)),
// with Fdr the cosine-weighted mean of F, so the base reflects albedo (1 - F(cos_o)) in all and the
// sum with the coat stays <= 1.
#include "engine/render/bsdf.hpp"
#include "engine/render/microfacet.hpp"

namespace lp::render {

class PlasticBsdf final : public Bsdf {
 public:
  PlasticBsdf(Rgb albedo, float ior, float roughness);
  // The same with the coat's diffuse_fresnel(ior) given (it costs an integral to compute).
  PlasticBsdf(Rgb albedo, float ior, float roughness, float diffuse_fresnel);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return true; }

  // The cosine-weighted hemispherical mean of the coat's reflectance, 2 * integral of F(mu) mu dmu.
  float diffuse_fresnel() const { return fdr_; }
  static float diffuse_fresnel(float ior);

 private:
  float fresnel(float cos_i) const;
  float specular_probability(float fresnel_o) const;
  Rgb eval_specular(Vec3 wo, Vec3 wi) const;
  float pdf_specular(Vec3 wo, Vec3 wi) const;
  Rgb eval_diffuse(Vec3 wo, Vec3 wi) const;

  Rgb albedo_;
  float ior_;
  bool delta_specular_;  // roughness below kDeltaLobeAlpha: the specular lobe is a mirror (delta)
  Ggx ggx_;
  float fdr_;
  float mean_albedo_;
};

}  // namespace lp::render
