#pragma once
// What `lightprobe render` renders, read by the API's parser (the same fields, defaults, limits and
// errors): a scene file, the JSON body of POST /api/v1/renders, or a model file (.gltf, .glb, .obj), which
// stands for the body whose scene is that one mesh with its own materials and no camera, so that the
// default camera fit frames it. Files are found as the tool finds them: "envmap" is a built-in map name
// (`default`) or a map file, and each mesh object's "path" a model file, a relative path being taken from
// the scene file's folder (for a model file, from the working directory). A map or model that cannot be
// read is a 400 invalid_field naming the field, as the API answers a missing map or a bad model.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "api/render_request.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/render/turntable.hpp"

namespace lp::cli {

struct SceneRender {
  api::RenderRequest request;  // its meshes' models loaded
  std::optional<render::Turntable> turntable;
  std::shared_ptr<const EnvMap> envmap;
};

// The body a model file stands for: {"envmap": "default", "scene": {"objects": [{"type": "mesh",
// "path": FILE}]}}.
api::Json model_body(const std::filesystem::path& model);

// Scene objects the command line adds (a JSON array), and the options that added them, for messages.
struct ExtraObjects {
  api::Json objects = api::Json::array();
  std::string options;
};

// `file`: a model file (model_format() names its format) or a scene file. `overrides`: top-level fields
// given on the command line, which replace the body's; a relative "envmap" path given there is taken from
// the working directory. With `turntable`, the body is that of a turntable request (that object its
// `turntable` field), read by its parser. `extra_objects` are appended to the body's scene objects (a scene
// without a list of objects, a preset, is then refused: bad_request).
SceneRender read_scene(const std::filesystem::path& file, const api::Json& overrides,
                       const ExtraObjects& extra_objects, const std::optional<api::Json>& turntable,
                       const api::RequestLimits& limits);

}  // namespace lp::cli
