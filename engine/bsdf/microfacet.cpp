#include "engine/bsdf/microfacet.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/fast_sincos.hpp"

namespace lp::render {

Ggx::Ggx(float alpha) : alpha_(std::max(alpha, 1e-4f)) {}

float Ggx::d(Vec3 m) const {
  if (m.z <= 0) return 0;
  const float a2 = alpha_ * alpha_;
  const float cos2 = m.z * m.z;
  const float k = cos2 * (a2 - 1.0f) + 1.0f;  // = cos^2 (a2 + tan^2) / ... rearranged
  return a2 / (kPiF * k * k);
}

float Ggx::lambda(Vec3 w) const {
  const float cos2 = w.z * w.z;
  if (cos2 <= 0) return 1e30f;
  const float sin2 = std::max(0.0f, 1.0f - cos2);
  const float a2_tan2 = alpha_ * alpha_ * sin2 / cos2;
  return 0.5f * (std::sqrt(1.0f + a2_tan2) - 1.0f);
}

Vec3 Ggx::sample_visible_normal(Vec3 wo, float u1, float u2) const {
  // Stretch the view direction to the hemisphere configuration (alpha = 1).
  const Vec3 vh = normalize(Vec3{alpha_ * wo.x, alpha_ * wo.y, wo.z});
  const float len2 = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = len2 > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(len2) : Vec3{1, 0, 0};
  const Vec3 t2 = cross(vh, t1);
  // A point on the projected disk, squeezed towards the visible half.
  const float r = std::sqrt(u1);
  const SinCos phi = sincos_turns(u2);
  const float p1 = r * phi.cos;
  float p2 = r * phi.sin;
  const float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  // Unstretch.
  return normalize(Vec3{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)});
}

float Ggx::visible_normal_pdf(Vec3 wo, Vec3 m) const {
  if (wo.z <= 0) return 0;
  return g1(wo) * std::max(0.0f, dot(wo, m)) * d(m) / wo.z;
}

std::optional<Vec3> Ggx::sample_reflection(Vec3 wo, float u1, float u2) const {
  const Vec3 h = sample_visible_normal(wo, u1, u2);
  if (dot(wo, h) <= 0) return std::nullopt;
  const Vec3 wi = reflect(wo, h);
  if (wi.z <= 0) return std::nullopt;
  return wi;
}

}  // namespace lp::render
