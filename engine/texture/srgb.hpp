#pragma once
// The sRGB transfer function (IEC 61966-2-1): encoded colour texture values to linear.
#include <cmath>

namespace lp {

inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace lp
