#pragma once
// A smooth dielectric boundary (glass): Fresnel-weighted choice between mirror reflection and
// refraction, total internal reflection included. Outside is z > 0, the inside has index `ior`.
#include "engine/bsdf/bsdf.hpp"

namespace lp::render {

class DielectricBsdf final : public Bsdf {
 public:
  explicit DielectricBsdf(float ior) : ior_(ior) {}
  Rgb eval(Vec3, Vec3) const override { return {}; }
  float pdf(Vec3, Vec3) const override { return 0; }
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return false; }
  bool two_sided() const override { return false; }

 private:
  float ior_;
};

}  // namespace lp::render
