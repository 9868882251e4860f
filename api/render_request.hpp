#pragma once
// The body of POST /api/v1/renders, parsed and validated into the renderer's plain data. Every failure is
// a 400 "invalid_field" naming the field by its path, e.g. "scene.objects[2].material.ior"; unknown fields
// are rejected at every level. Mesh paths are left as given; the server resolves and checks them inside its
// data directory.
#include <cstdint>
#include <optional>
#include <string>

#include "api/parameters.hpp"
#include "api/params.hpp"
#include "engine/render/scene_desc.hpp"
#include "engine/render/scene_view.hpp"

namespace lp::api {

// The request's field naming the auxiliary passes (render::AuxPass) kept beside the colour.
inline constexpr const char* kPassesField = "passes";

struct RenderRequest {
  std::string envmap;                 // id of a loaded map (checked by the server)
  std::optional<std::string> preset;  // the scene preset, if the scene named one
  render::SceneDesc scene;
  render::Lighting lighting;
  render::RenderSettings settings;
  ToneCurve tone_mapping = kRenderToneMapping.fallback;  // the default of its 8-bit pictures
  // The camera once the scene's models are loaded, and what the view leaves out (set by the server).
  std::optional<render::SceneView> view;
};

RenderRequest parse_render_request(const Json& body, const RequestLimits& limits);

// The limits a model a scene names is loaded under (--max-mesh-triangles and the texture pixel limits).
ModelLimits model_limits(const RequestLimits& limits);

}  // namespace lp::api
