#pragma once
// A perfect mirror tinted by a colour (a delta lobe).
#include "engine/bsdf/bsdf.hpp"

namespace lp::render {

class MirrorBsdf final : public Bsdf {
 public:
  explicit MirrorBsdf(Rgb color) : color_(color) {}
  Rgb eval(Vec3, Vec3) const override { return {}; }
  float pdf(Vec3, Vec3) const override { return 0; }
  std::optional<BsdfSample> sample(Vec3 wo, float, Point2) const override {
    if (wo.z <= 0) return std::nullopt;
    return BsdfSample{{-wo.x, -wo.y, wo.z}, color_, 1.0f, 1.0f, true};
  }
  bool has_non_delta_lobe() const override { return false; }

 private:
  Rgb color_;
};

}  // namespace lp::render
