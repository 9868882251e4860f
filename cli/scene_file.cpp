#include "cli/scene_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>

#include "api/api_error.hpp"
#include "api/parameters.hpp"
#include "api/turntable_request.hpp"
#include "cli/map_argument.hpp"
#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"

namespace lp::cli {
namespace {

api::Json read_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::NotFound, "cannot open the scene file " + file.string());
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return api::parse_json(text, "the scene file " + file.string());
}

std::shared_ptr<const EnvMap> load_scene_map(const std::string& envmap, const std::filesystem::path& base) {
  try {
    return load_map(envmap, kDefaultInvalidPixelPolicy, base).map;
  } catch (const Error& e) {
    throw api::invalid_field("envmap", e.what());
  }
}

void load_meshes(render::SceneDesc& scene, const std::filesystem::path& base, const ModelLimits& limits) {
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape);
    if (!mesh || mesh->model) continue;  // a preset's model is built in
    mesh->path = base / mesh->path;
    try {
      mesh->model = std::make_shared<const Model>(load_model(mesh->path, limits));
    } catch (const Error& e) {
      throw api::invalid_field(fmt::format("scene.objects[{}].path", i), e.what());
    }
  }
}

// Appends `objects` to the body's scene objects; a body without a list of objects (a preset, or no scene:
// the default preset) is refused, its objects being the preset's.
void append_objects(api::Json& body, const api::Json& objects, std::string_view options) {
  if (objects.empty() || !body.is_object()) return;
  api::Json* list = nullptr;
  if (const auto scene = body.find("scene"); scene != body.end() && scene->is_object())
    if (const auto found = scene->find("objects"); found != scene->end() && found->is_array()) list = &*found;
  if (!list)
    throw api::ApiError(api::ErrorCode::BadRequest,
                        fmt::format("{} adds to a scene's objects: this scene has none (a preset)", options));
  list->insert(list->end(), objects.begin(), objects.end());
}

}  // namespace

api::Json model_body(const std::filesystem::path& model) {
  return {{"envmap", "default"},
          {"scene", {{"objects", {{{"type", "mesh"}, {"path", model.string()}}}}}},
          {api::kThumbnailDenoise.name, api::kThumbnailDenoise.fallback}};
}

SceneRender read_scene(const std::filesystem::path& file, const api::Json& overrides,
                       const ExtraObjects& extra_objects, const std::optional<api::Json>& turntable,
                       const api::RequestLimits& limits) {
  const bool is_model = !model_format(file).empty();
  api::Json body = is_model ? model_body(file) : read_json(file);
  if (body.is_object()) body.update(overrides);
  append_objects(body, extra_objects.objects, extra_objects.options);
  // A model file's own path is already relative to the working directory, as is a map named on the
  // command line.
  const std::filesystem::path folder = is_model ? std::filesystem::path() : file.parent_path();
  SceneRender r;
  if (turntable) {
    if (body.is_object()) body["turntable"] = *turntable;
    api::TurntableRequest t = api::parse_turntable_request(body, limits);
    r.request = std::move(t.render);
    r.turntable = t.turntable;
  } else {
    r.request = api::parse_render_request(body, limits);
  }
  r.envmap = load_scene_map(r.request.envmap, overrides.contains("envmap") ? "" : folder);
  load_meshes(r.request.scene, folder, api::model_limits(limits));
  return r;
}

}  // namespace lp::cli
