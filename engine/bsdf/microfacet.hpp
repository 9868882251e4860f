#pragma once
// The isotropic GGX (Trowbridge-Reitz) microfacet distribution in the local frame (z = macro normal),
// with the height-correlated Smith masking-shadowing term and sampling of the distribution of visible
// normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
#include <optional>

#include "engine/core/vec3.hpp"

namespace lp::render {

// Below this alpha (roughness) a specular lobe is a delta, a perfect mirror: GGX in float degenerates there.
inline constexpr float kDeltaLobeAlpha = 1e-3f;

class Ggx {
 public:
  explicit Ggx(float alpha);

  float alpha() const { return alpha_; }
  // Normal distribution D(m), m a unit vector with m.z > 0.
  float d(Vec3 m) const;
  // Smith's Lambda(w) and the one-direction masking G1(w) = 1 / (1 + Lambda(w)).
  float lambda(Vec3 w) const;
  float g1(Vec3 w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing for a pair of directions.
  float g(Vec3 wo, Vec3 wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // A visible normal for a view direction `wo` (wo.z > 0), and its density D_wo(m) = G1(wo) max(0, wo.m) D(m)
  // / wo.z.
  Vec3 sample_visible_normal(Vec3 wo, float u1, float u2) const;
  float visible_normal_pdf(Vec3 wo, Vec3 m) const;

  // Reflection off the microfacets of half vector h = normalize(wo + wi), without its Fresnel factor:
  // D(h) G(wo, wi) / (4 wo.z); and the density of wi when h is sampled as a visible normal of wo.
  float reflection(Vec3 wo, Vec3 wi, Vec3 h) const { return d(h) * g(wo, wi) / (4.0f * wo.z); }
  float reflection_pdf(Vec3 wo, Vec3 h) const { return visible_normal_pdf(wo, h) / (4.0f * dot(wo, h)); }
  // wo reflected off a visible normal sampled for it (density reflection_pdf); nullopt when it points
  // below the surface.
  std::optional<Vec3> sample_reflection(Vec3 wo, float u1, float u2) const;

 private:
  float alpha_;
};

// Mirror reflection of w about the unit vector m.
inline Vec3 reflect(Vec3 w, Vec3 m) {
  return 2.0f * dot(w, m) * m - w;
}

}  // namespace lp::render
