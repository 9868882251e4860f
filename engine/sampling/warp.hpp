#pragma once
// Maps from the unit square to directions, with their solid-angle densities. The concentric map
// (Shirley & Chiu 1997) keeps the stratification of low-discrepancy points.
#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/fast_sincos.hpp"
#include "engine/core/vec3.hpp"

namespace lp {

struct Disk {
  float x, y;
};

inline Disk square_to_concentric_disk(float u1, float u2) {
  const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  if (a == 0 && b == 0) return {0, 0};
  float r, turns;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    turns = 0.125f * (b / a);
  } else {
    r = b;
    turns = 0.25f - 0.125f * (a / b);
  }
  const SinCos phi = sincos_turns(turns);
  return {r * phi.cos, r * phi.sin};
}

// Cosine-weighted hemisphere about +z: pdf = cos(theta) / pi.
inline Vec3 square_to_cosine_hemisphere(float u1, float u2) {
  const Disk d = square_to_concentric_disk(u1, u2);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}
inline float cosine_hemisphere_pdf(float cos_theta) {
  return std::max(0.0f, cos_theta) * (1.0f / kPiF);
}

// Uniform over the sphere: pdf = 1 / (4 pi).
inline Vec3 square_to_uniform_sphere(float u1, float u2) {
  const float z = 1.0f - 2.0f * u1;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const SinCos phi = sincos_turns(u2);
  return {r * phi.cos, r * phi.sin, z};
}
inline constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPiF);

}  // namespace lp
