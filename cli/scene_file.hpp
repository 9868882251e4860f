#pragma once
// A render described by a scene file: the JSON body of POST /api/v1/renders, read by the API's parser
// (the same fields, defaults, limits and errors), with its files found as the tool finds them: "envmap"
// is a built-in map name (`default`) or a map file, and each mesh object's "path" a model file (.gltf,
// .glb, .obj), a relative path being taken from the scene file's folder. A map or model that cannot be
// read is a 400 invalid_field naming the field, as the API answers a missing map or a bad model.
#include <filesystem>
#include <memory>

#include "api/render_request.hpp"
#include "engine/envmap/envmap.hpp"

namespace lp::cli {

struct SceneRender {
  api::RenderRequest request;  // its meshes' models loaded
  std::shared_ptr<const EnvMap> envmap;
};

// `overrides`: top-level fields given on the command line, which replace the file's; a relative
// "envmap" path given there is taken from the working directory.
SceneRender read_scene_file(const std::filesystem::path& file, const api::Json& overrides,
                            const api::RequestLimits& limits);

}  // namespace lp::cli
