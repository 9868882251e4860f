#pragma once
// KHR_materials_clearcoat's layer: a GGX reflection (alpha = clearcoatRoughness^2; a mirror, a delta
// lobe, when model_mirror(clearcoatRoughness), as for the extension's default roughness 0) off a
// dielectric of index 1.5 (F0 = 0.04, the extension's fixed coat), about its own normal (the clearcoat
// normal texture's, else the geometric one), with weight `clearcoat`.
// Exact dielectric Fresnel rather than Schlick's, so that its directional albedo is the tabulated E_F
// of the model's coat (microfacet_albedo.hpp). Single scattering only: a rough coat loses a little.
#include <optional>

#include "engine/bsdf/microfacet.hpp"
#include "engine/bsdf/microfacet_albedo.hpp"
#include "engine/core/frame.hpp"
#include "engine/core/point2.hpp"

namespace lp::render {

class ClearcoatLobe {
 public:
  // `normal`: the coat's normal in the BSDF's local frame (unit, z > 0).
  ClearcoatLobe(float weight, float roughness, Vec3 normal);

  // f |cos wi| (the cosine about the coat's normal), weight included; 0 below the coat and for a
  // mirror.
  Rgb eval(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  // A direction of the lobe; for a mirror, wo reflected about the coat's normal.
  std::optional<Vec3> sample(Vec3 wo, Point2 u) const;
  bool mirror() const { return mirror_; }
  // weight E_F(mu) for the direction w (either side: a transmitted ray crosses the coat too); for a
  // mirror, weight F(mu), which its one direction carries.
  float albedo(Vec3 w) const;

 private:
  float weight_;
  bool mirror_;
  Ggx ggx_;
  GgxAlbedo::Row albedo_;
  Frame frame_;
};

}  // namespace lp::render
