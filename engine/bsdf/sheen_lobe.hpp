#pragma once
// KHR_materials_sheen's lobe: the "Charlie" distribution of Estevez & Kulla (2017, "Production
// Friendly Microfacet Sheen BRDF"),
//   D(h) = (2 + 1 / alpha) sin(theta_h)^(1 / alpha) / (2 pi),   alpha = sheenRoughness^2,
// with the extension's simple (Neubelt) visibility V = 1 / (4 (mu_i + mu_o - mu_i mu_o)):
//   f = sheenColor D(h) V / max(1, E(mu_o), E(mu_i)),
// symmetric in wo and wi. The simple visibility is not energy conserving: at grazing angles and low
// roughness the lobe's directional albedo E (with a white colour) exceeds 1 (1.7 at sheenRoughness 0,
// 88 degrees), and the division holds it at 1 or below, reciprocally. Its directional albedo E(mu, alpha)
// with a white colour is tabulated at first use (a quadrature of this lobe over the hemisphere), for the
// layer's albedo scaling (bsdf_gltf_pbr.hpp). Sampled cosine-weighted: the lobe is broad.
#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"

namespace lp::render {

// Below this alpha the distribution is too peaked for the albedo table; the extension leaves the
// clamp to implementations (the sample viewer's is about 0.07^2).
inline constexpr float kMinSheenAlpha = 0.005f;

class SheenLobe {
 public:
  // `roughness` is sheenRoughness (perceptual), clamped to [0, 1].
  SheenLobe(Rgb color, float roughness);

  // f |cos wi| for wo, wi above the surface (else 0).
  Rgb eval(Vec3 wo, Vec3 wi) const;
  // At least the fraction of the light from mu that the lobe reflects, per unit of the colour's largest
  // channel, and at most 1: the layer beneath is scaled by 1 - max(color) albedo.
  float albedo(float cos_o) const;
  float strength() const { return max_component(color_); }

  static float pdf(Vec3 wi);
  static Vec3 sample(Point2 u);

 private:
  float raw_albedo(float cos_o) const;  // E of D V, white

  Rgb color_;
  float alpha_;
};

}  // namespace lp::render
