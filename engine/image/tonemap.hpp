#pragma once
// Linear radiance to 8-bit display values: scale by 2^exposure, apply the tone curve, then the display
// encoding (the sRGB curve, or a gamma). The curves are in engine/image/tone/curves.hpp.
#include <cstdint>

#include "engine/core/vec3.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/tone/display_encoding.hpp"

namespace lp {

// The curve alone: scaled linear RGB to display-linear RGB in [0, 1]. NaN and negative channels count
// as 0 (a negative has no light to show).
Vec3 apply_tone_curve(ToneCurve curve, Vec3 scaled);

// Precomputed per-call state so the per-pixel cost is a multiply, a curve and three table searches.
class ToneMapper {
 public:
  explicit ToneMapper(const ToneMap& tone);
  // One pixel: three linear floats in, three 8-bit display codes out.
  void operator()(const float* rgb, uint8_t* out) const;

 private:
  float scale_;
  ToneCurve curve_;
  tone::DisplayEncoding encode_;
};

}  // namespace lp
