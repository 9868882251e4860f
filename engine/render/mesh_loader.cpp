#include "engine/render/mesh_loader.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "engine/core/error.hpp"
#include "engine/model/obj_prescan.hpp"
#include "engine/render/mesh_transform.hpp"

namespace lp::render {
namespace {

std::string read_text(const std::filesystem::path& path, int64_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorKind::NotFound, "mesh not found: " + path.filename().string());
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(ErrorKind::NotFound, "mesh not readable: " + path.filename().string());
  if (int64_t(size) > max_bytes)
    throw Error(ErrorKind::TooLarge,
                "mesh file " + path.filename().string() + " is over " + std::to_string(max_bytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::NotFound, "mesh not readable: " + path.filename().string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int64_t check_obj_file(const std::filesystem::path& path, const MeshLimits& limits) {
  const std::string name = path.filename().string();
  return obj::check_obj_text(read_text(path, limits.max_file_bytes), name, limits.max_triangles);
}

TriangleMesh load_obj_mesh(const MeshObject& m, const MeshLimits& limits) {
  return obj_mesh_from_text(read_text(m.path, limits.max_file_bytes), m.path.filename().string(), m, limits);
}

TriangleMesh obj_mesh_from_text(const std::string& text, const std::string& name, const MeshObject& m,
                                const MeshLimits& limits) {
  check_mesh_transform(m);
  obj::check_obj_text(text, name, limits.max_triangles);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config))
    throw Error(ErrorKind::Corrupt, "mesh " + name + ": " + reader.Error());

  const auto& v = reader.GetAttrib().vertices;
  TriangleMesh mesh;
  mesh.positions.reserve(v.size() / 3);
  for (size_t i = 0; i + 2 < v.size(); i += 3) {
    Vec3 p{v[i], v[i + 1], v[i + 2]};
    if (!finite(p)) throw Error(ErrorKind::Corrupt, "mesh " + name + ": a vertex is not finite");
    mesh.positions.push_back(transform_mesh_point(m, p));
  }
  size_t index_count = 0;
  for (const auto& shape : reader.GetShapes()) index_count += shape.mesh.indices.size();
  if (int64_t(index_count / 3) > limits.max_triangles)
    throw Error(ErrorKind::TooLarge,
                "mesh " + name + " has over " + std::to_string(limits.max_triangles) + " triangles");
  mesh.indices.reserve(index_count);
  for (const auto& shape : reader.GetShapes()) {
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= mesh.positions.size())
        throw Error(ErrorKind::Corrupt, "mesh " + name + ": a face refers to a missing vertex");
      mesh.indices.push_back(uint32_t(idx.vertex_index));
    }
  }
  mesh.indices.resize(mesh.indices.size() / 3 * 3);
  if (mesh.indices.empty()) throw Error(ErrorKind::Corrupt, "mesh " + name + " has no triangles");
  return mesh;
}

int64_t mesh_memory_bytes(int64_t triangles) {
  // Peak resident bytes per triangle while a mesh is read and its BVH built (the file's text,
  // tinyobjloader's arrays, the TriangleMesh, Embree's BVH): 190 at 980k triangles and 133 at 20k in
  // bench/mesh_memory_bench, rounded up.
  constexpr int64_t kMeshBytesPerTriangle = 256;
  return triangles * kMeshBytesPerTriangle;
}

}  // namespace lp::render
