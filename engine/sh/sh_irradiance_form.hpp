#pragma once
// The irradiance of bands 0 to 2 as a quadratic form of the normal (Ramamoorthi and Hanrahan 2001,
// eq. 12): E(n) = n^T A n + b . n + c, one luminance, a dozen flops where evaluating the basis costs a
// hundred. For per-hit estimates such as the renderer's choice between the sun and the rest of the map.
#include "engine/core/vec3.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp {

class ShIrradianceForm {
 public:
  ShIrradianceForm() = default;
  // From irradiance coefficients (sh_irradiance) of at least 3 bands; RGB averaged into one luminance.
  explicit ShIrradianceForm(const ShCoefficients& irradiance);

  float operator()(Vec3 n) const {
    return c_ + b_.x * n.x + b_.y * n.y + b_.z * n.z + xx_ * n.x * n.x + yy_ * n.y * n.y + zz_ * n.z * n.z +
           xy_ * n.x * n.y + yz_ * n.y * n.z + xz_ * n.x * n.z;
  }

 private:
  float c_ = 0, xx_ = 0, yy_ = 0, zz_ = 0, xy_ = 0, yz_ = 0, xz_ = 0;
  Vec3 b_{};
};

}  // namespace lp
