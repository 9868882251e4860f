#pragma once
// glTF's base material with KHR_materials_ior, _specular and _transmission (the glTF BRDF reference,
// Appendix B of the glTF 2.0 specification): mix(dielectric, metal, metallic), where the dielectric is
//   fresnel_mix(specular lobe, mix(diffuse, transmission, transmissionFactor))
// with Schlick's F = F0 + (F90 - F0) (1 - |v.h|)^5,
//   F0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specular,   F90 = specular.
// The metal is the core model's (bsdf_metallic_roughness.hpp).
// Energy, as in the plastic model (bsdf_plastic.hpp): the specular lobe (GGX with its
// multiple-scattering compensation) reflects E_s(mu) per channel, linear in F0 and F90 through the
// tabulated albedos of F = 1 and F = (1 - c)^5; the rest, 1 - max(E_s(mu_o)), goes to
//   diffuse:      base (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (pi (1 - E_s,avg)), reciprocal, albedo
//                 exactly base (1 - E_s(mu_o));
//   transmission: base (1 - E_s(mu_o)) times a lobe of albedo 1: a thin wall sends the light on
//                 through (the GGX lobe mirrored through the surface: straight on when smooth); a
//                 thick one refracts it into the volume by Snell's law about a visible GGX normal
//                 (the refraction lobe of bsdf_rough_dielectric.hpp; by the surface's normal when
//                 smooth).
// A smooth surface (model_mirror(roughness)) reflects and transmits as delta lobes; E_s is then Schlick's
// F itself. A thick transmitting surface is one-sided: from inside (wo.z < 0) it is a dielectric
// interface of index ior of the same roughness (bsdf_rough_dielectric.hpp; bsdf_dielectric.hpp when
// smooth). An index of 1 makes no interface: the light goes straight on.
#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/bsdf_metallic_roughness.hpp"
#include "engine/bsdf/bsdf_rough_dielectric.hpp"
#include "engine/bsdf/microfacet_multiscatter.hpp"

namespace lp::render {

struct GltfBaseParams {
  Rgb base_color{1, 1, 1};
  float metallic = 1;
  float roughness = 1;  // perceptual
  float ior = kModelDielectricIor;
  float specular = 1;
  Rgb specular_color{1, 1, 1};
  float transmission = 0;
  bool thin_walled = true;  // KHR_materials_volume's thickness 0
};

class GltfBaseBsdf final : public Bsdf {
 public:
  explicit GltfBaseBsdf(const GltfBaseParams& p);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return !mirror_ || (metallic_ < 1 && transmission_ < 1); }
  bool two_sided() const override { return thin_walled_ || transmission_ <= 0; }

  // The largest channel of E_s(mu): the part of the light the specular lobe takes.
  float specular_albedo(float cos_o) const;

 private:
  struct Choice {
    float metal, specular, diffuse, transmission;
  };
  Choice choice(float cos_o) const;
  float mean_specular_albedo() const;
  Rgb schlick(float cos_d) const;
  Rgb eval_specular(Vec3 wo, Vec3 wi) const;
  Rgb eval_diffuse(Vec3 wo, Vec3 wi) const;
  Rgb transmission_tint(float cos_o) const;  // what the transmission lobe carries, of albedo 1
  Rgb eval_transmission(Vec3 wo, Vec3 wi) const;
  float transmission_pdf(Vec3 wo, Vec3 wi) const;
  std::optional<BsdfSample> sample_transmission(Vec3 wo, float probability) const;
  std::optional<BsdfSample> sample_from_inside(Vec3 wo, float u_lobe, Point2 u) const;
  BsdfSample weighted(Vec3 wo, Vec3 wi) const;

  Rgb base_;
  float metallic_;
  float ior_;
  float transmission_;
  bool thin_walled_;
  bool mirror_;  // model_mirror(roughness): reflection and transmission are delta lobes
  Rgb f0_;
  float f90_;
  int max_channel_;  // the channel of the largest F0: that of the largest E_s at every angle
  CompensatedGgx lobe_;
  GgxAlbedo::Row e1_, e5_;  // E_F for F = 1 and for F = (1 - c)^5
  Rgb ms_fresnel_;
  float specular_average_;  // cosine-weighted mean of specular_albedo
  MetallicRoughnessBsdf metal_;
  std::optional<RoughDielectricBsdf> interface_;  // a thick, rough surface's boundary
};

}  // namespace lp::render
