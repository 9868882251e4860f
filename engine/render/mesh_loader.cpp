#include "engine/render/mesh_loader.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/model/model.hpp"
#include "engine/render/obj_prescan.hpp"

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

Vec3 rotate_axis(Vec3 v, int axis, float degrees) {
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

void check_transform(const MeshObject& m) {
  if (!(std::isfinite(m.scale) && m.scale > 0) || !finite(m.translate) || !finite(m.rotate_deg))
    throw Error(ErrorKind::InvalidArgument, "mesh: scale must be > 0 and the transform finite");
}

Vec3 place(Vec3 p, const MeshObject& m) {
  p = p * m.scale;
  p = rotate_axis(rotate_axis(rotate_axis(p, 0, m.rotate_deg.x), 1, m.rotate_deg.y), 2, m.rotate_deg.z);
  return p + m.translate;
}

}  // namespace

int64_t check_obj_file(const std::filesystem::path& path, const MeshLimits& limits) {
  const std::string name = path.filename().string();
  return check_obj_text(read_text(path, limits.max_file_bytes), name, limits.max_triangles);
}

TriangleMesh load_obj_mesh(const MeshObject& m, const MeshLimits& limits) {
  return obj_mesh_from_text(read_text(m.path, limits.max_file_bytes), m.path.filename().string(), m, limits);
}

TriangleMesh obj_mesh_from_text(const std::string& text, const std::string& name, const MeshObject& m,
                                const MeshLimits& limits) {
  check_transform(m);
  check_obj_text(text, name, limits.max_triangles);
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
    mesh.positions.push_back(place(p, m));
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

TriangleMesh placed_model_mesh(const Model& model, const MeshObject& m) {
  check_transform(m);
  if (model.indices.empty())
    throw Error(ErrorKind::Corrupt, "mesh " + m.path.filename().string() + " has no triangles");
  TriangleMesh mesh;
  mesh.positions.reserve(model.positions.size());
  for (const Vec3& p : model.positions) mesh.positions.push_back(place(p, m));
  mesh.indices = model.indices;
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
