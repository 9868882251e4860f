#pragma once
// glTF's metallic-roughness material as a mix of two of our models, weighted by `metallic`:
//   dielectric part (1 - metallic): the plastic model (bsdf_plastic.hpp), a GGX coat of index 1.5
//     (F0 = 0.04, glTF's dielectric) over a diffuse base of the base colour;
//   metallic part: GGX reflection with Schlick's Fresnel of F0 = base colour, and the energy its single
//     scattering loses given back (microfacet_multiscatter.hpp; F_avg of Schlick's F is
//     F0 + (1 - F0) / 21 in closed form).
// Both use GGX alpha = roughness^2; below kDeltaLobeAlpha (roughness under 0.032, glTF's default clear
// coat and polished chrome or glass) the specular lobes are mirrors (delta lobes), as in Cycles, so a
// small bright source such as the sun keeps its full radiance in the reflection. A part is picked with
// probability (1 - metallic) / metallic.
#include "engine/bsdf/bsdf.hpp"
#include "engine/bsdf/bsdf_plastic.hpp"
#include "engine/bsdf/microfacet_multiscatter.hpp"

namespace lp::render {

inline constexpr float kModelDielectricIor = 1.5f;

// GGX alpha of a glTF perceptual roughness: roughness^2 (roughness clamped to [0, 1]).
float model_alpha(float roughness);
// True when a glTF roughness makes a mirror: its alpha is below kDeltaLobeAlpha.
bool model_mirror(float roughness);
// The coat of index kModelDielectricIor with its albedo tables, shared by every model surface
// (computed at first use).
const DielectricCoat& model_coat();

class MetallicRoughnessBsdf final : public Bsdf {
 public:
  // `roughness` is glTF's perceptual roughness; metallic and roughness are clamped to [0, 1].
  MetallicRoughnessBsdf(Rgb base_color, float metallic, float roughness);
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return !(metal_mirror_ && metallic_ >= 1); }

 private:
  Rgb eval_metal(Vec3 wo, Vec3 wi) const;

  Rgb base_;
  float metallic_;
  bool metal_mirror_;  // model_mirror(roughness): the metallic part is a delta lobe
  CompensatedGgx metal_;
  Rgb metal_ms_fresnel_;  // F_ms of the metallic part
  PlasticBsdf dielectric_;
};

}  // namespace lp::render
