#include "server/renders/scene_meshes.hpp"

#include <fmt/format.h>

#include <variant>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "engine/core/error.hpp"
#include "engine/render/placed_model.hpp"
#include "engine/render/scene_view.hpp"
#include "server/assets/mesh_paths.hpp"

namespace lp::server {
namespace {

void check_up_axis(const render::MeshObject& mesh, const std::string& prefix) {
  try {
    render::file_to_world(mesh, *mesh.model);
  } catch (const Error& e) {
    throw api::invalid_field(prefix + ".up_axis", e.what());
  }
}

}  // namespace

void resolve_view(api::RenderRequest& request) {
  const auto& s = request.settings;
  api::as_invalid_field([&] {
    request.view = render::resolve_view(request.scene, float(s.width) / float(std::max(1, s.height)));
  });
  request.scene.camera = request.view->camera;  // the job renders it as resolved, without framing again
}

int64_t resolve_meshes(render::SceneDesc& scene, App& app) {
  return resolve_meshes(scene, app, [&app](size_t, const std::string& path, const std::string& field) {
    return resolve_mesh_path(app, path, field);
  });
}

int64_t resolve_meshes(render::SceneDesc& scene, App& app, const MeshLocator& locate) {
  int64_t triangles = 0;
  const ModelLimits limits = api::model_limits(app.options.limits);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape);
    if (!mesh) continue;
    if (mesh->model) {
      app.models.hold_builtin(mesh->model, "the " + mesh->path.string() + " preset's model");
    } else {
      const std::string field = fmt::format("scene.objects[{}].path", i);
      mesh->path = locate(i, mesh->path.string(), field);
      try {
        mesh->model = app.models.get(mesh->path, limits);
      } catch (const MemoryBudgetError&) {
        throw;
      } catch (const Error& e) {
        throw api::invalid_field(field, e.what());
      }
      check_up_axis(*mesh, fmt::format("scene.objects[{}]", i));
    }
    triangles += int64_t(mesh->model->triangle_count());
  }
  return triangles;
}

}  // namespace lp::server
