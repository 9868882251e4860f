#include <algorithm>
#include <cmath>

#include "engine/image/tone/curves.hpp"

namespace lp::tone {
namespace {

constexpr float kF90 = 0.04f;                     // Fresnel at normal incidence of IoR 1.5
constexpr float kStartCompression = 0.8f - kF90;  // K_s
constexpr float kDesaturation = 0.15f;            // K_d
constexpr float kD = 1.0f - kStartCompression;
constexpr float kToe = 1.0f / (4.0f * kF90);  // the toe is x - kToe x^2 below 2 F90

float min3(Vec3 c) {
  return std::min(c.x, std::min(c.y, c.z));
}
float max3(Vec3 c) {
  return std::max(c.x, std::max(c.y, c.z));
}
Vec3 grey(float v) {
  return {v, v, v};
}

}  // namespace

Vec3 pbr_neutral(Vec3 c) {
  const float x = min3(c);
  const float offset = x < 2.0f * kF90 ? x - kToe * x * x : kF90;
  c = c - grey(offset);
  const float peak = max3(c);
  if (peak < kStartCompression) return c;
  const float new_peak = 1.0f - kD * kD / (peak + kD - kStartCompression);
  c *= new_peak / peak;
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
  return c * (1.0f - g) + grey(new_peak * g);
}

Vec3 pbr_neutral_inverse(Vec3 c) {
  const float peak = max3(c);
  if (peak > kStartCompression) {
    const float old_peak = kD * kD / (1.0f - peak) - kD + kStartCompression;
    const float f_inv = kDesaturation * (old_peak - peak) + 1.0f;
    c = (c + grey((1.0f / f_inv - 1.0f) * peak)) * f_inv;
    c *= old_peak / peak;
  }
  const float y = min3(c);
  float offset = kF90;
  if (y < kF90) {
    const float x = std::sqrt(y / kToe);
    offset = x - kToe * x * x;
  }
  return c + grey(offset);
}

}  // namespace lp::tone
