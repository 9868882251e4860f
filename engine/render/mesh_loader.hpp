#pragma once
// Triangle meshes from Wavefront OBJ files (tinyobjloader), transformed into the world: scale, then
// rotations about x, y and z (degrees), then translation. Materials (.mtl) are never read.
#include <cstdint>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct TriangleMesh {
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;  // three per triangle
  size_t triangle_count() const { return indices.size() / 3; }
};

// Throws lp::Error: NotFound (no such file), TooLarge (over the limits), Corrupt (unparseable, no
// triangles, indices out of range, non-finite vertices), InvalidArgument (bad transform).
TriangleMesh load_obj_mesh(const MeshObject& mesh, const MeshLimits& limits);

}  // namespace lp::render
