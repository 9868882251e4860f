#pragma once
// The Ggx reflection lobe with energy compensation for the light it loses to multiple scattering, after
// Kulla & Conty ("Revisiting Physically Based Shading at Imageworks", SIGGRAPH 2017 course). With F = 1
// the single-scattering lobe reflects E(mu_o) of the light (microfacet_albedo.hpp); on a real surface
// the rest scatters again among the microfacets and leaves. A second, diffuse-like lobe returns it:
//   f_ms(wo, wi) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
// reciprocal, with albedo exactly 1 - E(mu_o), so that with F = 1 the two reflect everything. Under a
// Fresnel factor each further bounce reflects only part of the light, and the compensation is scaled by
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
// F_avg the cosine-weighted mean of F: the light leaving after k >= 2 bounces, each reflecting F_avg
// and letting E_avg escape, summed over k and divided by the white lobe's 1 - E_avg. F_ms <= F_avg, so
// the lobes together reflect at most E + (1 - E) = 1.
// Turquin (2019) and Cycles scale the single-scattering lobe by 1 + F0 (1 - E) / E instead, which has
// no lobe of its own to sample but is not reciprocal; here the compensation is a lobe, sampled
// cosine-weighted.
#include <optional>

#include "engine/bsdf/microfacet.hpp"
#include "engine/bsdf/microfacet_albedo.hpp"
#include "engine/core/point2.hpp"

namespace lp::render {

class CompensatedGgx {
 public:
  explicit CompensatedGgx(float alpha);

  const Ggx& ggx() const { return ggx_; }

  // The compensation's albedo 1 - E(mu_o) and its cosine-weighted mean 1 - E_avg, with F = 1 (0 for a
  // lobe too sharp to lose anything measurable).
  float multiscatter_albedo(float cos_o) const { return scale_ > 0 ? 1.0f - albedo_(cos_o) : 0.0f; }
  float multiscatter_average() const { return scale_ > 0 ? 1.0f - albedo_.average() : 0.0f; }
  // f_ms |cos wi| with F = 1.
  float multiscatter(float cos_o, float cos_i) const {
    return multiscatter_albedo(cos_o) * multiscatter_albedo(cos_i) * cos_i * scale_;
  }
  // F_ms for a Fresnel factor whose cosine-weighted mean is f_avg (per channel).
  float multiscatter_fresnel(float f_avg) const;
  Rgb multiscatter_fresnel(Rgb f_avg) const {
    return {multiscatter_fresnel(f_avg.x), multiscatter_fresnel(f_avg.y), multiscatter_fresnel(f_avg.z)};
  }

  // f |cos wi| of both lobes, for a Fresnel factor fresnel(wo.h) (an Rgb) with F_ms = ms_fresnel.
  template <class Fresnel>
  Rgb eval(Vec3 wo, Vec3 wi, const Fresnel& fresnel, Rgb ms_fresnel) const {
    const Vec3 h = normalize(wo + wi);
    return fresnel(dot(wo, h)) * ggx_.reflection(wo, wi, h) + ms_fresnel * multiscatter(wo.z, wi.z);
  }

  // Sampling of both lobes, for wo and wi above the surface: the single-scattering lobe by visible
  // normals, the compensation cosine-weighted, picked in proportion to their albedos with F = 1.
  float multiscatter_probability(float cos_o) const { return multiscatter_albedo(cos_o); }
  float pdf(Vec3 wo, Vec3 wi) const;
  // nullopt when the reflection off the sampled microfacet points below the surface.
  std::optional<Vec3> sample(Vec3 wo, float u_lobe, Point2 u) const;

 private:
  Ggx ggx_;
  GgxAlbedo::Row albedo_;  // E with F = 1
  float scale_;            // 1 / (pi (1 - E_avg)), or 0
};

}  // namespace lp::render
