#pragma once
// glTF's PBR material with its layers, as the glTF BRDF reference composes them: KHR_materials_clearcoat
// over KHR_materials_sheen over the base (bsdf_gltf_base.hpp; the core metallic-roughness model,
// unchanged, when the base uses none of ior, specular and transmission). Each layer scales what lies
// beneath by the spec's albedo scaling, made symmetric as the sheen extension writes it:
//   f = coat + s_c (sheen + s_s base),   s_x(wo, wi) = min(1 - E_x(mu_o), 1 - E_x(mu_i)),
// E_c = clearcoat E_F(mu) of the coat, E_s = max(sheenColor) E_sheen(mu). A layer thus never adds
// energy (what it reflects from wo is taken from the light the layer beneath receives) and keeps
// reciprocity. Lobes are sampled in proportion to their estimated albedos at wo.
#include <optional>

#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/bsdf_gltf_base.hpp"
#include "engine/bsdf/bsdf_metallic_roughness.hpp"
#include "engine/bsdf/clearcoat_lobe.hpp"
#include "engine/bsdf/sheen_lobe.hpp"

namespace lp::render {

struct GltfPbrParams {
  GltfBaseParams base;
  float clearcoat = 0;
  float clearcoat_roughness = 0;   // perceptual
  Vec3 clearcoat_normal{0, 0, 1};  // in the BSDF's local frame
  Rgb sheen_color{0, 0, 0};
  float sheen_roughness = 0;  // perceptual

  // True when the base is the core metallic-roughness model (ior 1.5, no specular change, no
  // transmission).
  bool core_base() const;
};

class GltfPbrBsdf final : public Bsdf {
 public:
  explicit GltfPbrBsdf(const GltfPbrParams& p);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override {
    return base().has_non_delta_lobe() || sheen_ || (coat_ && !coat_->mirror());
  }
  bool two_sided() const override { return base().two_sided(); }

  // The clearcoat's normal in the local frame (unit; one at or below the surface is taken as z).
  void set_clearcoat_normal(Vec3 normal);

 private:
  struct Choice {
    float coat, sheen, base;
  };
  const Bsdf& base() const;
  Choice choice(Vec3 wo) const;
  float layer_scale(Vec3 wo, Vec3 wi) const;  // s_c s_s
  std::optional<BsdfSample> weighted(Vec3 wo, Vec3 wi) const;

  std::optional<MetallicRoughnessBsdf> core_;
  std::optional<GltfBaseBsdf> extended_;
  std::optional<ClearcoatLobe> coat_;
  std::optional<SheenLobe> sheen_;
  float clearcoat_, clearcoat_roughness_;
  float base_estimate_;  // the base's albedo, roughly: its share of the samples
};

}  // namespace lp::render
