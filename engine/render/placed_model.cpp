#include "engine/render/placed_model.hpp"

#include "engine/model/model_loader.hpp"
#include "engine/render/mesh_transform.hpp"

namespace lp::render {

Mat4 file_to_world(const MeshObject& mesh, const Model& model) {
  if (!model.up_axis_unstated) {
    if (mesh.up_axis == UpAxis::Z)
      throw Error(ErrorKind::InvalidArgument,
                  "a glTF model is y-up by its specification; z applies to OBJ files");
    return Mat4{};
  }
  return up_axis_to_world(mesh.up_axis.value_or(kDefaultUpAxis));
}

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
  const Mat4 frame = file_to_world(mesh, model);
  for (Vec3& p : model.positions) p = transform_mesh_point(mesh, frame.point(p));
  for (Vec3& n : model.normals) n = normalize(rotate_mesh_direction(mesh, frame.vector(n)));
  for (Tangent& t : model.tangents)
    t.direction = normalize(rotate_mesh_direction(mesh, frame.vector(t.direction)));
  model.up_axis_unstated = false;
  return model;
}

}  // namespace lp::render
