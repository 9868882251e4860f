#pragma once
// The transfer functions OIDN's rt filters apply to the colour before the network and invert after it:
// HDR values go through the perceptually uniform (PU) curve scaled so that 65504 maps to 1, LDR values
// through the sRGB curve.
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/image/image.hpp"

namespace lp::denoise {

inline constexpr float kFloatMax = std::numeric_limits<float>::max();

// NaN to zero, then clamped to [lo, hi] (infinities to the bounds), as OIDN cleans its inputs and outputs.
inline float sanitize(float v, float lo, float hi) {
  return std::isnan(v) ? std::clamp(0.f, lo, hi) : std::clamp(v, lo, hi);
}

enum class Transfer { Srgb, Pu };

float transfer_forward(Transfer t, float y);
float transfer_inverse(Transfer t, float x);

// OIDN's autoexposure: 0.18 over the geometric mean of the luminance of 16x16 bins (bins darker than 1e-8
// left out), 1 for a black image (and for one so bright that the scale would underflow).
float autoexposure(const Image& color);

}  // namespace lp::denoise
