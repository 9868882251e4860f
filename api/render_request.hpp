#pragma once
// The body of POST /api/v1/renders, parsed and validated into the renderer's plain data. Every failure is
// a 400 "invalid_field" naming the field by its path, e.g. "scene.objects[2].material.ior"; unknown fields
// are rejected at every level. Mesh paths are left as given; the server resolves and checks them inside its
// data directory.
#include <cstdint>
#include <optional>
#include <string>

#include "api/params.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::api {

struct RenderLimits {
  int max_width = 4096;
  int max_height = 4096;
  int max_spp = 65536;
  int max_depth = 64;
  int max_objects = 256;
  int max_lights = 65536;  // median-cut lights
  int64_t max_mesh_triangles = 2'000'000;  // per mesh, checked by the renderer while loading
};

struct RenderRequest {
  std::string envmap;                 // id of a loaded map (checked by the server)
  std::optional<std::string> preset;  // the scene preset, if the scene named one
  render::SceneDesc scene;
  render::Lighting lighting;
  render::RenderSettings settings;
};

RenderRequest parse_render_request(const Json& body, const RenderLimits& limits);

const char* lighting_mode_name(render::LightingMode mode);  // "envmap", "uniform", ...

}  // namespace lp::api
