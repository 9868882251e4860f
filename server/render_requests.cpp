#include "server/render_requests.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "api/api_error.hpp"
#include "engine/core/error.hpp"
#include "engine/render/mesh_loader.hpp"
#include "server/mesh_paths.hpp"

namespace lp::server {

int64_t resolve_meshes(render::SceneDesc& scene, const App& app) {
  int64_t triangles = 0;
  render::MeshLimits limits;
  limits.max_triangles = app.options.limits.max_mesh_triangles;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape);
    if (!mesh) continue;
    const std::string field = fmt::format("scene.objects[{}].path", i);
    mesh->path = resolve_mesh_path(app, mesh->path.string(), field);
    try {
      triangles += render::check_obj_file(mesh->path, limits);
    } catch (const Error& e) {
      throw api::invalid_field(field, e.what());
    }
  }
  return triangles;
}

}  // namespace lp::server
