#pragma once
// A diffuse base under a dielectric coat (after Mitsuba's plastic / roughplastic, layered as Kulla &
// Conty do). The coat reflects with the dielectric Fresnel reflectance F: as a mirror (a delta lobe)
// when smooth, otherwise as GGX with its multiple-scattering compensation (microfacet_multiscatter.hpp;
// F_avg = Fdr, the cosine-weighted mean of F). Let E_c(mu) be all the coat reflects of the light
// arriving from mu:
//   smooth: E_c(mu) = F(mu);   rough: E_c(mu) = E_F(mu) + F_ms (1 - E(mu)),
// E_F the albedo of the single-scattering lobe with F (tabulated per index, microfacet_albedo.hpp) and
// F_ms (1 - E) that of the compensation. The rest, 1 - E_c, enters the base, is scattered and leaves
// through the coat again:
//   f_d = albedo (1 - E_c(mu_o)) (1 - E_c(mu_i)) / (pi (1 - E_c,avg)),
// reciprocal, with albedo exactly albedo (1 - E_c(mu_o)) since E_c,avg is the cosine-weighted mean of
// E_c. So a white plastic reflects E_c + (1 - E_c) = 1, smooth or rough, and any other less; smooth,
// f_d is the classic (1 - F)(1 - F) / (1 - Fdr).
// Sampling: the coat's single-scattering lobe by visible normals; its compensation and the base, both
// diffuse-like, cosine-weighted; in proportion to their albedos.
#include <memory>

#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/microfacet_albedo.hpp"
#include "engine/bsdf/microfacet_multiscatter.hpp"

namespace lp::render {

// A coat of index `ior` (outside: air): the cosine-weighted mean of its Fresnel reflectance, Fdr, and
// the albedo E_F of its single-scattering GGX lobe.
struct DielectricCoat {
  explicit DielectricCoat(float index);      // E_F for every alpha in [0, 1] (tens of milliseconds)
  DielectricCoat(float index, float alpha);  // for that alpha only (a few milliseconds)

  float ior;
  float fresnel_average;
  GgxAlbedo single_scattering;
};

class PlasticBsdf final : public Bsdf {
 public:
  // Tabulates its coat at its own roughness: for a material's BSDF, made once per render.
  PlasticBsdf(Rgb albedo, float ior, float roughness);
  // With the coat's tables given (alpha = roughness; `coat` must outlive the BSDF): for BSDFs made
  // per hit.
  PlasticBsdf(Rgb albedo, float roughness, const DielectricCoat& coat);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return true; }

  // The cosine-weighted hemispherical mean of the coat's reflectance, 2 * integral of F(mu) mu dmu.
  float diffuse_fresnel() const { return coat_->fresnel_average; }

 private:
  PlasticBsdf(Rgb albedo, float roughness, std::shared_ptr<const DielectricCoat> owned,
              const DielectricCoat* coat);
  float fresnel(float cos_i) const;
  float coat_albedo(float cos_o) const;  // E_c
  float specular_probability(float cos_o) const;
  Rgb eval_specular(Vec3 wo, Vec3 wi) const;
  Rgb eval_diffuse(Vec3 wo, Vec3 wi) const;

  Rgb albedo_;
  bool delta_specular_;  // roughness below kDeltaLobeAlpha: the specular lobe is a mirror (delta)
  std::shared_ptr<const DielectricCoat> owned_coat_;  // when made by the first constructor
  const DielectricCoat* coat_;
  CompensatedGgx lobe_;
  GgxAlbedo::Row single_scattering_;  // E_F at this roughness
  float ms_fresnel_;                  // F_ms for F_avg = Fdr
  float coat_average_;                // E_c,avg
  float mean_albedo_;
};

}  // namespace lp::render
