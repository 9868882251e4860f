#pragma once
// A mesh object's placement in the world: scale, then rotations about x, y and z (degrees), then
// translation.
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/core/vec3.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

inline Vec3 rotate_axis(Vec3 v, int axis, float degrees) {
  const float a = degrees * kPiF / 180.0f, c = std::cos(a), s = std::sin(a);
  switch (axis) {
    case 0:
      return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
    case 1:
      return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
    default:
      return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
  }
}

// A direction (normal or tangent) turned with the object; the uniform scale leaves it unchanged.
inline Vec3 rotate_mesh_direction(const MeshObject& m, Vec3 v) {
  return rotate_axis(rotate_axis(rotate_axis(v, 0, m.rotate_deg.x), 1, m.rotate_deg.y), 2, m.rotate_deg.z);
}

inline void check_mesh_transform(const MeshObject& m) {
  if (!(std::isfinite(m.scale) && m.scale > 0) || !finite(m.translate) || !finite(m.rotate_deg))
    throw Error(ErrorKind::InvalidArgument, "mesh: scale must be > 0 and the transform finite");
}

inline Vec3 transform_mesh_point(const MeshObject& m, Vec3 p) {
  return rotate_mesh_direction(m, p * m.scale) + m.translate;
}

}  // namespace lp::render
