#include "api/render_request.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "api/excerpt.hpp"
#include "api/sun_request.hpp"
#include "engine/core/validate.hpp"
#include "engine/fresnel/metals.hpp"

namespace lp::api {
namespace {

using namespace lp::render;

// Values are read as finite numbers here; their ranges are the engine's (validate() in scene_desc.hpp).
std::string field_name(const std::string& prefix, const std::string& name) {
  return field_path(prefix, name);
}

const Json* member(const Json& parent, const std::string& name) {
  auto it = parent.find(name);
  return it == parent.end() || it->is_null() ? nullptr : &*it;
}

// The member as an object (nullptr if absent); 400 if it is something else.
const Json* object_member(const Json& parent, const std::string& name, const std::string& prefix) {
  const Json* v = member(parent, name);
  if (v && !v->is_object())
    throw invalid_field(field_name(prefix, name), fmt::format("must be an object, got {}", describe(*v)));
  return v;
}

float component(const Json& v, const std::string& field) {
  if (!v.is_number()) throw invalid_field(field, fmt::format("must be a number, got {}", describe(v)));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw invalid_field(field, "must be finite");
  return float(x);
}

// [x, y, z]; nullopt if absent.
std::optional<Vec3> json_vec3(const Json& parent, const std::string& name, const std::string& prefix) {
  const Json* v = member(parent, name);
  if (!v) return std::nullopt;
  const std::string field = field_name(prefix, name);
  if (!v->is_array() || v->size() != 3)
    throw invalid_field(field, fmt::format("must be an array of 3 numbers, got {}", describe(*v)));
  return Vec3{component((*v)[0], field + "[0]"), component((*v)[1], field + "[1]"),
              component((*v)[2], field + "[2]")};
}

Vec3 required_vec3(const Json& parent, const std::string& name, const std::string& prefix) {
  auto v = json_vec3(parent, name, prefix);
  if (!v) throw invalid_field(field_name(prefix, name), "is required");
  return *v;
}

// A colour: one number (grey) or [r, g, b].
Rgb json_rgb(const Json& parent, const std::string& name, const std::string& prefix, Rgb fallback) {
  const Json* v = member(parent, name);
  if (!v) return fallback;
  if (v->is_number()) {
    const float g = component(*v, field_name(prefix, name));
    return {g, g, g};
  }
  return *json_vec3(parent, name, prefix);
}

// A required string that must be one of `allowed`.
std::string required_enum(const Json& parent, const std::string& name,
                          const std::vector<std::string>& allowed, const std::string& prefix) {
  const std::string v = json_string(parent, name, std::nullopt, prefix);
  return json_enum(parent, name, v, allowed, prefix);
}

// An integer in [min, the server's limit], whose default also respects the limit.
int bounded_int(const Json& parent, const std::string& name, int fallback, int64_t min, int64_t limit) {
  const int64_t max = std::min<int64_t>(limit, std::numeric_limits<int>::max());
  return int(json_int(parent, name, std::min<int64_t>(fallback, max), min, max));
}

// A finite number (its range is checked by the engine's validate()).
float json_float(const Json& parent, const std::string& name, double fallback, const std::string& prefix) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return float(json_double(parent, name, fallback, -kMax, kMax, prefix));
}

Material parse_conductor(const Json& m, const std::string& prefix) {
  reject_unknown_fields(m, {"type", "metal", "eta", "k", "roughness"}, prefix);
  ConductorMaterial c;
  c.roughness = json_float(m, "roughness", c.roughness, prefix);
  const bool has_metal = member(m, "metal"), has_eta = member(m, "eta"), has_k = member(m, "k");
  if (has_metal) {
    if (has_eta || has_k)
      throw invalid_field(field_name(prefix, "metal"), "give either metal or eta and k, not both");
    const auto& names = metal_names();
    const std::string metal = json_enum(m, "metal", names.front(), names, prefix);
    c.eta = lookup_metal(metal).eta_rgb();
    c.k = lookup_metal(metal).k_rgb();
  } else {
    if (!has_eta || !has_k)
      throw invalid_field(field_name(prefix, has_eta ? "k" : "eta"),
                          "is required (give metal, e.g. \"gold\", or both eta and k)");
    c.eta = json_rgb(m, "eta", prefix, {});
    c.k = json_rgb(m, "k", prefix, {});
  }
  return c;
}

Material parse_material(const Json* m, const std::string& prefix) {
  if (!m) return DiffuseMaterial{};
  const std::string type =
      required_enum(*m, "type", {"diffuse", "mirror", "dielectric", "plastic", "conductor"}, prefix);
  if (type == "diffuse") {
    reject_unknown_fields(*m, {"type", "albedo"}, prefix);
    return DiffuseMaterial{json_rgb(*m, "albedo", prefix, DiffuseMaterial{}.albedo)};
  }
  if (type == "mirror") {
    reject_unknown_fields(*m, {"type", "color"}, prefix);
    return MirrorMaterial{json_rgb(*m, "color", prefix, MirrorMaterial{}.color)};
  }
  if (type == "dielectric") {
    reject_unknown_fields(*m, {"type", "ior", "roughness"}, prefix);
    const DielectricMaterial d;
    return DielectricMaterial{json_float(*m, "ior", d.ior, prefix),
                              json_float(*m, "roughness", d.roughness, prefix)};
  }
  if (type == "plastic") {
    reject_unknown_fields(*m, {"type", "albedo", "ior", "roughness"}, prefix);
    const PlasticMaterial d;
    return PlasticMaterial{json_rgb(*m, "albedo", prefix, d.albedo), json_float(*m, "ior", d.ior, prefix),
                           json_float(*m, "roughness", d.roughness, prefix)};
  }
  return parse_conductor(*m, prefix);
}

MeshObject parse_mesh(const Json& o, const std::string& prefix) {
  MeshObject mesh;
  mesh.path = json_string(o, "path", std::nullopt, prefix);  // resolved in the data directory by the server
  if (member(o, "up_axis")) mesh.up_axis = json_enum(o, "up_axis", kDefaultUpAxis, prefix);
  if (const Json* t = object_member(o, "transform", prefix)) {
    const std::string tp = field_name(prefix, "transform");
    reject_unknown_fields(*t, {"translate", "scale", "rotate_deg"}, tp);
    mesh.translate = json_vec3(*t, "translate", tp).value_or(mesh.translate);
    mesh.scale = json_float(*t, "scale", mesh.scale, tp);
    mesh.rotate_deg = json_vec3(*t, "rotate_deg", tp).value_or(mesh.rotate_deg);
  }
  return mesh;
}

SceneObject parse_object(const Json& o, const std::string& prefix) {
  if (!o.is_object()) throw invalid_field(prefix, fmt::format("must be an object, got {}", describe(o)));
  const std::string type = required_enum(o, "type", {"sphere", "mesh", "plane", "ground"}, prefix);
  SceneObject object;
  if (type == "ground") {
    reject_unknown_fields(o, {"type", "shadow_catcher", "height", "material"}, prefix);
    render::Ground ground;
    ground.shadow_catcher = json_bool(o, "shadow_catcher", ground.shadow_catcher, prefix);
    if (member(o, "height")) ground.height = json_float(o, "height", 0, prefix);
    object.shape = PlaneObject{{0, 0, ground.height.value_or(0.0f)}, {0, 0, 1}};
    object.ground = ground;
  } else if (type == "sphere") {
    reject_unknown_fields(o, {"type", "center", "radius", "material"}, prefix);
    SphereObject s;
    s.center = required_vec3(o, "center", prefix);
    if (!member(o, "radius")) throw invalid_field(field_name(prefix, "radius"), "is required");
    s.radius = json_float(o, "radius", s.radius, prefix);
    object.shape = s;
  } else if (type == "plane") {
    reject_unknown_fields(o, {"type", "point", "normal", "material"}, prefix);
    PlaneObject p;
    p.point = required_vec3(o, "point", prefix);
    p.normal = required_vec3(o, "normal", prefix);
    object.shape = p;
  } else {
    reject_unknown_fields(o, {"type", "path", "up_axis", "transform", "material"}, prefix);
    MeshObject mesh = parse_mesh(o, prefix);
    mesh.model_materials = !member(o, "material");  // a material given overrides the model's own
    object.shape = std::move(mesh);
  }
  object.material = parse_material(object_member(o, "material", prefix), field_name(prefix, "material"));
  return object;
}

// An object index: a whole number, its range checked by the scene's validate().
std::optional<uint32_t> object_index(const Json& parent, const std::string& prefix) {
  if (!member(parent, "object")) return std::nullopt;
  return uint32_t(json_int(parent, "object", 0, 0, std::numeric_limits<uint32_t>::max(), prefix));
}

render::CameraFit parse_fit(const Json& f, const std::string& prefix) {
  reject_unknown_fields(f, {"object", "azimuth_deg", "elevation_deg", "margin"}, prefix);
  render::CameraFit fit;
  fit.object = object_index(f, prefix);
  fit.azimuth_deg = json_float(f, "azimuth_deg", fit.azimuth_deg, prefix);
  fit.elevation_deg = json_float(f, "elevation_deg", fit.elevation_deg, prefix);
  fit.margin = json_float(f, "margin", fit.margin, prefix);
  return fit;
}

// A glTF camera: its index or name alone, or {"camera": index or name, "object": i}.
render::GltfCameraChoice parse_gltf_camera(const Json& g, const std::string& prefix) {
  render::GltfCameraChoice choice;
  const Json* which = &g;
  if (g.is_object()) {
    reject_unknown_fields(g, {"camera", "object"}, prefix);
    choice.object = object_index(g, prefix);
    which = member(g, "camera");
    if (!which) throw invalid_field(field_name(prefix, "camera"), "is required");
  }
  const std::string field = g.is_object() ? field_name(prefix, "camera") : prefix;
  if (which->is_string()) {
    choice.name = which->get<std::string>();
  } else if (which->is_number_integer() && which->get<int64_t>() >= 0 &&
             which->get<int64_t>() <= std::numeric_limits<uint32_t>::max()) {
    choice.index = uint32_t(which->get<int64_t>());
  } else {
    throw invalid_field(field, fmt::format("must be a camera's index (a whole number >= 0) or name, got {}",
                                           describe(*which)));
  }
  return choice;
}

Camera parse_camera(const Json& c, Camera camera) {
  const std::string prefix = "scene.camera";
  reject_unknown_fields(c, {"position", "look_at", "up", "fov_deg", "fit", "gltf"}, prefix);
  const Json* fit = member(c, "fit");
  const Json* gltf = member(c, "gltf");
  for (const char* placed : {"position", "look_at", "up"})
    if ((fit || gltf) && member(c, placed))
      throw invalid_field(field_name(prefix, placed),
                          fmt::format("not allowed with {}", field_name(prefix, fit ? "fit" : "gltf")));
  if (fit && gltf) throw invalid_field(field_name(prefix, "fit"), "not allowed with scene.camera.gltf");
  camera.position = json_vec3(c, "position", prefix).value_or(camera.position);
  camera.look_at = json_vec3(c, "look_at", prefix).value_or(camera.look_at);
  camera.up = json_vec3(c, "up", prefix).value_or(camera.up);
  camera.fov_deg = json_float(c, "fov_deg", camera.fov_deg, prefix);
  camera.fit.reset();
  camera.gltf.reset();
  if (fit) {
    if (!fit->is_object())
      throw invalid_field(field_name(prefix, "fit"),
                          fmt::format("must be an object, got {}", describe(*fit)));
    camera.fit = parse_fit(*fit, field_name(prefix, "fit"));
  }
  if (gltf) camera.gltf = parse_gltf_camera(*gltf, field_name(prefix, "gltf"));
  return camera;
}

SceneDesc parse_scene(const Json* s, const RequestLimits& limits, std::optional<std::string>& preset) {
  const Json empty = Json::object();
  if (!s) s = &empty;  // no scene, or neither objects nor preset: the "sphere" preset
  reject_unknown_fields(*s, {"preset", "camera", "objects"}, "scene");
  const Json* objects = member(*s, "objects");
  if (objects && member(*s, "preset")) throw invalid_field("scene.objects", "not allowed with scene.preset");
  SceneDesc scene;
  if (objects) {
    if (!objects->is_array())
      throw invalid_field("scene.objects", fmt::format("must be an array, got {}", describe(*objects)));
    if (int64_t(objects->size()) > limits.max_render_objects)
      throw invalid_field("scene.objects", fmt::format("{} objects is over the limit of {}", objects->size(),
                                                       limits.max_render_objects));
    for (size_t i = 0; i < objects->size(); ++i)
      scene.objects.push_back(parse_object((*objects)[i], fmt::format("scene.objects[{}]", i)));
  } else {
    const auto chosen = json_enum(*s, "preset", render::ScenePreset::Sphere, "scene");
    preset = enum_name(chosen);
    scene = render::preset_scene(chosen);
  }
  if (const Json* c = object_member(*s, "camera", "scene"))
    scene.camera = parse_camera(*c, scene.camera);
  else if (std::any_of(scene.objects.begin(), scene.objects.end(), [](const render::SceneObject& o) {
             return !std::holds_alternative<render::PlaneObject>(o.shape);
           }))
    scene.camera.fit = render::CameraFit{};  // objects, no camera: framed from the front, slightly above
  return scene;
}

Lighting parse_lighting(const Json* l, const RequestLimits& limits) {
  Lighting lighting;
  const int max_lights = int(std::min<int64_t>(limits.max_lights, std::numeric_limits<int>::max()));
  lighting.lights = std::min(lighting.lights, max_lights);
  if (!l) return lighting;
  const std::string prefix = "lighting";
  reject_unknown_fields(
      *l, {"mode", "sun", "sun_parameters", "lights", "rotation_deg", "intensity", "visible"}, prefix);
  lighting.mode = json_enum(*l, "mode", lighting.mode, prefix);
  lighting.sun = json_enum(*l, "sun", lighting.sun, prefix);
  if (const Json* p = object_member(*l, "sun_parameters", prefix))
    lighting.sun_parameters = parse_sun_params(*p, field_name(prefix, "sun_parameters"));
  lighting.lights = int(json_int(*l, "lights", lighting.lights, 1, max_lights, prefix));
  lighting.rotation_deg = json_float(*l, "rotation_deg", lighting.rotation_deg, prefix);
  lighting.intensity = json_float(*l, "intensity", lighting.intensity, prefix);
  lighting.visible = json_bool(*l, "visible", lighting.visible, prefix);
  return lighting;
}

// "map", "transparent" or a linear colour [r, g, b].
render::Background parse_background(const Json& body) {
  render::Background b;
  const Json* v = member(body, "background");
  if (!v) return b;
  if (v->is_array()) {
    b.mode = render::BackgroundMode::Color;
    b.color = *json_vec3(body, "background", "");
    return b;
  }
  const std::vector<std::string> allowed = {enum_name(render::BackgroundMode::Map),
                                            enum_name(render::BackgroundMode::Transparent)};
  if (!v->is_string())
    throw invalid_field("background", fmt::format("must be '{}', '{}' or a colour [r, g, b], got {}",
                                                  allowed[0], allowed[1], describe(*v)));
  b.mode = *parse_enum<render::BackgroundMode>(json_enum(body, "background", allowed.front(), allowed));
  return b;
}

// Names of auxiliary passes, each at most once.
render::PassSet parse_passes(const Json& body) {
  render::PassSet passes;
  const Json* v = member(body, kPassesField);
  if (!v) return passes;
  const std::string names = enum_names_joined<render::AuxPass>();
  if (!v->is_array())
    throw invalid_field(kPassesField,
                        fmt::format("must be an array of pass names ({}), got {}", names, describe(*v)));
  for (size_t i = 0; i < v->size(); ++i) {
    const std::string field = fmt::format("{}[{}]", kPassesField, i);
    const Json& name = (*v)[i];
    const auto pass = name.is_string() ? parse_enum<render::AuxPass>(name.get<std::string>()) : std::nullopt;
    if (!pass) throw invalid_field(field, fmt::format("must be one of {}, got {}", names, describe(name)));
    if (passes.has(*pass)) throw invalid_field(field, fmt::format("'{}' is named twice", enum_name(*pass)));
    passes.add(*pass);
  }
  return passes;
}

}  // namespace

RenderRequest parse_render_request(const Json& body, const RequestLimits& limits, const BoolField& denoise) {
  if (!body.is_object()) throw ApiError(ErrorCode::InvalidJson, "the request body must be a JSON object");
  reject_unknown_fields(body, {"envmap", "scene", "lighting", "width", "height", "spp", "max_depth", "seed",
                               "mipmaps", "normal_maps", "sampling", kRenderToneMapping.name, "background",
                               "clamp", kPassesField, denoise.name});
  RenderRequest r;
  r.envmap = json_string(body, "envmap", std::nullopt);
  if (r.envmap.empty()) throw invalid_field("envmap", "must not be empty");
  r.scene = parse_scene(object_member(body, "scene", ""), limits, r.preset);
  r.lighting = parse_lighting(object_member(body, "lighting", ""), limits);
  const RenderSettings d;
  r.settings.width = bounded_int(body, "width", d.width, 1, limits.max_render_width);
  r.settings.height = bounded_int(body, "height", d.height, 1, limits.max_render_height);
  r.settings.spp = bounded_int(body, "spp", d.spp, 1, limits.max_render_spp);
  r.settings.max_depth =
      bounded_int(body, "max_depth", d.max_depth, limits::kMaxDepth.min, limits.max_render_depth);
  r.settings.mesh_limits.max_triangles = limits.max_mesh_triangles;
  r.settings.seed = uint64_t(json_int(body, "seed", int64_t(d.seed), 0, std::numeric_limits<int64_t>::max()));
  r.settings.mipmaps = json_bool(body, "mipmaps", d.mipmaps);
  r.settings.normal_maps = json_bool(body, "normal_maps", d.normal_maps);
  r.settings.sampling = json_enum(body, "sampling", d.sampling, "");
  r.tone_mapping = json_enum(body, kRenderToneMapping.name, kRenderToneMapping.fallback);
  r.settings.background = parse_background(body);
  if (member(body, "clamp")) r.settings.clamp = json_float(body, "clamp", 0, "");
  r.settings.passes = parse_passes(body);
  // A cut-out's pictures are RGBA: its alpha is always kept.
  if (r.settings.background.mode == BackgroundMode::Transparent) r.settings.passes.add(AuxPass::Alpha);
  // The denoiser takes the colour with its albedo and normal.
  r.denoise = json_bool(body, denoise.name, denoise.fallback);
  for (const AuxPass p : {AuxPass::Albedo, AuxPass::Normal})
    if (r.denoise && !r.settings.passes.has(p)) {
      r.settings.passes.add(p);
      r.denoise_passes.add(p);
    }
  as_invalid_field([&] {
    r.scene.validate("scene");
    r.lighting.validate("lighting");
    r.settings.validate("");
  });
  for (SceneObject& o : r.scene.objects)
    if (auto* plane = std::get_if<PlaneObject>(&o.shape)) plane->normal = normalize(plane->normal);
  return r;
}

ModelLimits model_limits(const RequestLimits& limits) {
  ModelLimits m;
  m.max_triangles = limits.max_mesh_triangles;
  m.max_texture_pixels = limits.max_texture_pixels;
  m.max_total_texture_pixels = limits.max_model_texture_pixels;
  return m;
}

}  // namespace lp::api
