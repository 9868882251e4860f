#pragma once
// The world frame models enter: z up, as Blender's. glTF is y-up with its front facing +z; it enters as
// Blender's glTF importer puts it, glTF (x, y, z) -> world (x, -z, y), so its up becomes +z and its front
// faces -y, towards a camera on the -y axis. OBJ states no convention; its file is read y-up (the common
// exporters' choice) or z-up as the scene says.
#include "engine/core/enum_table.hpp"
#include "engine/model/mat4.hpp"

namespace lp {

enum class UpAxis { Y, Z };
constexpr auto enum_entries(UpAxis) {
  return std::to_array<EnumEntry<UpAxis>>({{UpAxis::Y, "y"}, {UpAxis::Z, "z"}});
}
inline constexpr UpAxis kDefaultUpAxis = UpAxis::Y;

// The rotation taking a y-up model's coordinates into the world: +90 degrees about x.
inline Mat4 y_up_to_world() {
  Mat4 r;
  r.m[5] = 0;   // (1, 1)
  r.m[6] = 1;   // (2, 1): world z = y
  r.m[9] = -1;  // (1, 2): world y = -z
  r.m[10] = 0;  // (2, 2)
  return r;
}

inline Mat4 up_axis_to_world(UpAxis up) {
  return up == UpAxis::Y ? y_up_to_world() : Mat4{};
}

}  // namespace lp
