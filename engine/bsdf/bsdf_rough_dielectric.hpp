#pragma once
// A rough dielectric boundary (frosted glass): GGX microfacets that reflect and refract, after Walter et
// al. 2007, "Microfacet Models for Refraction through Rough Surfaces", with the height-correlated Smith
// masking of microfacet.hpp and the exact dielectric Fresnel factor. Outside is z > 0, the inside has
// index `ior`; wo may lie on either side (inside, the indices swap).
//
// For wo on the side of index n_o and wi on the side of index n_i (eta = n_i / n_o, 1 for a reflection),
// with m the microfacet normal that sends wo into wi (the half vector of a reflection, the generalised
// half vector +-normalize(wo + eta wi) of a refraction, facing z > 0):
//   reflection  f = F D G / (4 |wo.z| |wi.z|)
//   refraction  f = (1 - F) D G |wo.m| |wi.m| / (|wo.z| |wi.z| (wo.m + eta wi.m)^2)
// where F = F(wo.m). The refraction is Walter's BTDF scaled by 1 / eta^2 (radiance transport, bsdf.hpp),
// so it obeys the generalised reciprocity f(wo, wi) / n_o^2 == f(wi, wo) / n_i^2 (a reflection is
// plainly reciprocal).
//
// Sampling: a visible normal m of wo (Heitz 2018) on wo's side, then reflection with probability F(wo.m),
// else refraction by Snell's law about m (total internal reflection always reflects). A direction that
// ends up on the wrong side of the macro surface gives no sample. The sample weight is
// G(wo, wi) / G1(wo), divided by eta^2 for a refraction.
#include <optional>

#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/microfacet.hpp"

namespace lp::render {

class RoughDielectricBsdf final : public Bsdf {
 public:
  // ior > 0 and != 1 (matched media have no interface); alpha >= kDeltaLobeAlpha (below it the boundary
  // is smooth: DielectricBsdf).
  RoughDielectricBsdf(float ior, float alpha);

  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return true; }
  bool two_sided() const override { return false; }

  // The refraction lobe alone, from the outside in, with no Fresnel factor and no radiance scaling: for a
  // material that splits the energy between its lobes itself.
  // sample_refraction: wo (wo.z > 0) refracted by Snell's law about a visible normal of wo into the inside;
  // nullopt when wo.z <= 0, under total internal reflection (only for ior < 1) or when the refracted
  // direction does not point below the surface.
  std::optional<Vec3> sample_refraction(Vec3 wo, Point2 u) const;
  // The solid-angle density of wi under sample_refraction, D_wo(m) |dm/dwi| with m the generalised half
  // vector; 0 unless wo.z > 0 > wi.z. Its integral over the lower hemisphere is at most 1: the rest is the
  // samples that sample_refraction refuses.
  float refraction_pdf(Vec3 wo, Vec3 wi) const;

 private:
  struct Value {
    float f_cos = 0;  // f(wo, wi) |cos wi|
    float pdf = 0;
  };
  Value evaluate(Vec3 wo, Vec3 wi) const;

  float ior_;
  Ggx ggx_;
};

}  // namespace lp::render
