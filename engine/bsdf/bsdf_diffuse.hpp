#pragma once
// Lambertian reflection with cosine-weighted sampling.
#include "engine/bsdf/bsdf.hpp"

namespace lp::render {

class DiffuseBsdf final : public Bsdf {
 public:
  explicit DiffuseBsdf(Rgb albedo) : albedo_(albedo) {}
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Point2 u) const override;
  bool has_non_delta_lobe() const override { return true; }

 private:
  Rgb albedo_;
};

}  // namespace lp::render
