#pragma once
// Triangle meshes from Wavefront OBJ files (tinyobjloader), transformed into the world: scale, then
// rotations about x, y and z (degrees), then translation. Materials (.mtl) are never read.
#include <cstdint>
#include <filesystem>
#include <string>
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
// The same from the file's text; `name` appears in messages.
TriangleMesh obj_mesh_from_text(const std::string& text, const std::string& name, const MeshObject& mesh,
                                const MeshLimits& limits);
// The triangles of a loaded model, placed by the mesh object's transform. Throws lp::Error
// InvalidArgument (bad transform) or Corrupt (no triangles).
TriangleMesh placed_model_mesh(const Model& model, const MeshObject& mesh);
// Reads the file and refuses what load_obj_mesh would refuse before parsing (see obj_prescan.hpp),
// so that a request can be answered at once. Returns the number of triangles the mesh will have.
int64_t check_obj_file(const std::filesystem::path& path, const MeshLimits& limits);

// Memory a mesh of `triangles` takes while a render holds it: the parsed file, the TriangleMesh and
// Embree's scene and BVH (measured: see kMeshBytesPerTriangle).
int64_t mesh_memory_bytes(int64_t triangles);

}  // namespace lp::render
