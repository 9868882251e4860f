#include "engine/render/placed_model.hpp"

#include "engine/model/model_loader.hpp"
#include "engine/render/mesh_transform.hpp"

namespace lp::render {

Model place_model(const MeshObject& mesh, const MeshLimits& limits) {
  check_mesh_transform(mesh);
  Model model;
  if (mesh.model) {
    model = *mesh.model;
  } else {
    ModelLimits model_limits;
    model_limits.max_triangles = limits.max_triangles;
    model_limits.max_file_bytes = limits.max_file_bytes;
    model = load_model(mesh.path, model_limits);
  }
  for (Vec3& p : model.positions) p = transform_mesh_point(mesh, p);
  for (Vec3& n : model.normals) n = normalize(rotate_mesh_direction(mesh, n));
  for (Tangent& t : model.tangents) t.direction = normalize(rotate_mesh_direction(mesh, t.direction));
  return model;
}

}  // namespace lp::render
