#pragma once
// 3x3 colour matrices (rows) for the tone curves' changes of primaries.
#include "engine/core/vec3.hpp"

namespace lp::tone {

struct Mat3 {
  Vec3 r0, r1, r2;  // rows: out.x = dot(r0, in), ...
};

constexpr Vec3 operator*(const Mat3& m, Vec3 v) {
  return {dot(m.r0, v), dot(m.r1, v), dot(m.r2, v)};
}

// The inverse (the matrices here are well conditioned: no check of the determinant).
constexpr Mat3 inverse(const Mat3& m) {
  const Vec3 c0 = cross(m.r1, m.r2), c1 = cross(m.r2, m.r0), c2 = cross(m.r0, m.r1);
  const float inv_det = 1.0f / dot(m.r0, c0);
  // The columns of the inverse are the cross products over the determinant.
  return {Vec3{c0.x, c1.x, c2.x} * inv_det, Vec3{c0.y, c1.y, c2.y} * inv_det,
          Vec3{c0.z, c1.z, c2.z} * inv_det};
}

}  // namespace lp::tone
