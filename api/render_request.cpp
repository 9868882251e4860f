#include "api/render_request.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "api/api_error.hpp"
#include "api/excerpt.hpp"
#include "engine/fresnel/metals.hpp"

namespace lp::api {
namespace {

using namespace lp::render;

constexpr double kMaxCoordinate = 1e6;  // scene coordinates and sizes
constexpr double kMaxIor = 4.0;

std::string field_name(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "." + name;
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

float component(const Json& v, const std::string& field, double min, double max) {
  if (!v.is_number()) throw invalid_field(field, fmt::format("must be a number, got {}", describe(v)));
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < min || x > max)
    throw invalid_field(field, fmt::format("{} is out of range [{}, {}]", x, min, max));
  return float(x);
}

// [x, y, z] with every component in [min, max]; nullopt if absent.
std::optional<Vec3> json_vec3(const Json& parent, const std::string& name, const std::string& prefix,
                              double min, double max) {
  const Json* v = member(parent, name);
  if (!v) return std::nullopt;
  const std::string field = field_name(prefix, name);
  if (!v->is_array() || v->size() != 3)
    throw invalid_field(field, fmt::format("must be an array of 3 numbers, got {}", describe(*v)));
  return Vec3{component((*v)[0], field + "[0]", min, max), component((*v)[1], field + "[1]", min, max),
              component((*v)[2], field + "[2]", min, max)};
}

Vec3 required_vec3(const Json& parent, const std::string& name, const std::string& prefix) {
  auto v = json_vec3(parent, name, prefix, -kMaxCoordinate, kMaxCoordinate);
  if (!v) throw invalid_field(field_name(prefix, name), "is required");
  return *v;
}

// A colour: one number (grey) or [r, g, b], each in [min, max].
Rgb json_rgb(const Json& parent, const std::string& name, const std::string& prefix, Rgb fallback, double min,
             double max) {
  const Json* v = member(parent, name);
  if (!v) return fallback;
  if (v->is_number()) {
    const float g = component(*v, field_name(prefix, name), min, max);
    return {g, g, g};
  }
  return *json_vec3(parent, name, prefix, min, max);
}

// A required string that must be one of `allowed`.
std::string required_enum(const Json& parent, const std::string& name,
                          const std::vector<std::string>& allowed, const std::string& prefix) {
  const std::string v = json_string(parent, name, std::nullopt, prefix);
  return json_enum(parent, name, v, allowed, prefix);
}

// An integer whose default also respects the server's limit.
int bounded_int(const Json& parent, const std::string& name, int fallback, int min, int max) {
  return int(json_int(parent, name, std::min(fallback, max), min, max));
}

float json_float(const Json& parent, const std::string& name, double fallback, double min, double max,
                 const std::string& prefix) {
  return float(json_double(parent, name, fallback, min, max, prefix));
}

Vec3 nonzero_direction(Vec3 v, const std::string& field) {
  if (!(length(v) > 1e-9f)) throw invalid_field(field, "must not be the zero vector");
  return normalize(v);
}

Material parse_conductor(const Json& m, const std::string& prefix) {
  reject_unknown_fields(m, {"type", "metal", "eta", "k", "roughness"}, prefix);
  ConductorMaterial c;
  c.roughness = json_float(m, "roughness", 0.0, 0.0, 1.0, prefix);
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
    c.eta = json_rgb(m, "eta", prefix, {}, 0.001, 20.0);
    c.k = json_rgb(m, "k", prefix, {}, 0.0, 20.0);
  }
  return c;
}

Material parse_material(const Json* m, const std::string& prefix) {
  if (!m) return DiffuseMaterial{};
  const std::string type =
      required_enum(*m, "type", {"diffuse", "mirror", "dielectric", "plastic", "conductor"}, prefix);
  if (type == "diffuse") {
    reject_unknown_fields(*m, {"type", "albedo"}, prefix);
    return DiffuseMaterial{json_rgb(*m, "albedo", prefix, DiffuseMaterial{}.albedo, 0.0, 1.0)};
  }
  if (type == "mirror") {
    reject_unknown_fields(*m, {"type", "color"}, prefix);
    return MirrorMaterial{json_rgb(*m, "color", prefix, MirrorMaterial{}.color, 0.0, 1.0)};
  }
  if (type == "dielectric") {
    reject_unknown_fields(*m, {"type", "ior"}, prefix);
    return DielectricMaterial{json_float(*m, "ior", DielectricMaterial{}.ior, 1.0, kMaxIor, prefix)};
  }
  if (type == "plastic") {
    reject_unknown_fields(*m, {"type", "albedo", "ior", "roughness"}, prefix);
    const PlasticMaterial d;
    return PlasticMaterial{json_rgb(*m, "albedo", prefix, d.albedo, 0.0, 1.0),
                           json_float(*m, "ior", d.ior, 1.0, kMaxIor, prefix),
                           json_float(*m, "roughness", d.roughness, 0.0, 1.0, prefix)};
  }
  return parse_conductor(*m, prefix);
}

// Checked and resolved inside the data directory by the server (server/data_dir.hpp).
std::filesystem::path mesh_path(const Json& o, const std::string& prefix) {
  const std::string text = json_string(o, "path", std::nullopt, prefix);
  if (text.empty()) throw invalid_field(field_name(prefix, "path"), "must not be empty");
  return text;
}

MeshObject parse_mesh(const Json& o, const std::string& prefix) {
  MeshObject mesh;
  mesh.path = mesh_path(o, prefix);
  if (const Json* t = object_member(o, "transform", prefix)) {
    const std::string tp = field_name(prefix, "transform");
    reject_unknown_fields(*t, {"translate", "scale", "rotate_deg"}, tp);
    mesh.translate = json_vec3(*t, "translate", tp, -kMaxCoordinate, kMaxCoordinate).value_or(Vec3{});
    mesh.scale = json_float(*t, "scale", 1.0, 1e-6, kMaxCoordinate, tp);
    mesh.rotate_deg = json_vec3(*t, "rotate_deg", tp, -360.0, 360.0).value_or(Vec3{});
  }
  return mesh;
}

SceneObject parse_object(const Json& o, const std::string& prefix) {
  if (!o.is_object()) throw invalid_field(prefix, fmt::format("must be an object, got {}", describe(o)));
  const std::string type = required_enum(o, "type", {"sphere", "mesh", "plane"}, prefix);
  SceneObject object;
  if (type == "sphere") {
    reject_unknown_fields(o, {"type", "center", "radius", "material"}, prefix);
    SphereObject s;
    s.center = required_vec3(o, "center", prefix);
    if (!member(o, "radius")) throw invalid_field(field_name(prefix, "radius"), "is required");
    s.radius = json_float(o, "radius", 1.0, 1e-6, kMaxCoordinate, prefix);
    object.shape = s;
  } else if (type == "plane") {
    reject_unknown_fields(o, {"type", "point", "normal", "material"}, prefix);
    PlaneObject p;
    p.point = required_vec3(o, "point", prefix);
    p.normal = nonzero_direction(required_vec3(o, "normal", prefix), field_name(prefix, "normal"));
    object.shape = p;
  } else {
    reject_unknown_fields(o, {"type", "path", "transform", "material"}, prefix);
    object.shape = parse_mesh(o, prefix);
  }
  object.material = parse_material(object_member(o, "material", prefix), field_name(prefix, "material"));
  return object;
}

Camera parse_camera(const Json& c, Camera camera) {
  const std::string prefix = "scene.camera";
  reject_unknown_fields(c, {"position", "look_at", "up", "fov_deg"}, prefix);
  camera.position =
      json_vec3(c, "position", prefix, -kMaxCoordinate, kMaxCoordinate).value_or(camera.position);
  camera.look_at = json_vec3(c, "look_at", prefix, -kMaxCoordinate, kMaxCoordinate).value_or(camera.look_at);
  camera.up = json_vec3(c, "up", prefix, -kMaxCoordinate, kMaxCoordinate).value_or(camera.up);
  camera.fov_deg = json_float(c, "fov_deg", camera.fov_deg, 1.0, 179.0, prefix);
  const Vec3 view = camera.look_at - camera.position;
  if (!(length(view) > 1e-6f))
    throw invalid_field(prefix + ".look_at", "must differ from scene.camera.position");
  const Vec3 up = nonzero_direction(camera.up, prefix + ".up");
  if (length(cross(normalize(view), up)) < 1e-4f)
    throw invalid_field(prefix + ".up", "must not be parallel to the viewing direction (look_at - position)");
  return camera;
}

SceneDesc parse_scene(const Json* s, const RenderLimits& limits, std::optional<std::string>& preset) {
  const Json empty = Json::object();
  if (!s) s = &empty;  // no scene, or neither objects nor preset: the "sphere" preset
  reject_unknown_fields(*s, {"preset", "camera", "objects"}, "scene");
  const Json* objects = member(*s, "objects");
  if (objects && member(*s, "preset")) throw invalid_field("scene.objects", "not allowed with scene.preset");
  SceneDesc scene;
  if (objects) {
    if (!objects->is_array())
      throw invalid_field("scene.objects", fmt::format("must be an array, got {}", describe(*objects)));
    if (int64_t(objects->size()) > limits.max_objects)
      throw invalid_field("scene.objects", fmt::format("{} objects is over the limit of {}", objects->size(),
                                                       limits.max_objects));
    for (size_t i = 0; i < objects->size(); ++i)
      scene.objects.push_back(parse_object((*objects)[i], fmt::format("scene.objects[{}]", i)));
  } else {
    preset = json_enum(*s, "preset", "sphere", {"sphere", "materials", "furnace"}, "scene");
    auto found = scene_preset(*preset);
    if (!found)
      throw invalid_field("scene.preset", fmt::format("preset '{}' is not available", excerpt(*preset)));
    scene = std::move(*found);
  }
  if (const Json* c = object_member(*s, "camera", "scene")) scene.camera = parse_camera(*c, scene.camera);
  return scene;
}

Lighting parse_lighting(const Json* l, const RenderLimits& limits) {
  Lighting lighting;
  lighting.lights = std::min(lighting.lights, limits.max_lights);
  if (!l) return lighting;
  const std::string prefix = "lighting";
  reject_unknown_fields(*l, {"mode", "lights", "rotation_deg", "intensity", "visible"}, prefix);
  const std::vector<std::string> modes = {"envmap", "uniform", "bsdf", "median_cut", "median_cut_all"};
  const std::string mode = json_enum(*l, "mode", "envmap", modes, prefix);
  lighting.mode = LightingMode(std::find(modes.begin(), modes.end(), mode) - modes.begin());
  lighting.lights = int(json_int(*l, "lights", lighting.lights, 1, limits.max_lights, prefix));
  lighting.rotation_deg = json_float(*l, "rotation_deg", 0.0, -360.0, 360.0, prefix);
  lighting.intensity = json_float(*l, "intensity", 1.0, 0.0, 1e6, prefix);
  lighting.visible = json_bool(*l, "visible", true, prefix);
  return lighting;
}

}  // namespace

const char* lighting_mode_name(LightingMode mode) {
  switch (mode) {
    case LightingMode::EnvMap:
      return "envmap";
    case LightingMode::Uniform:
      return "uniform";
    case LightingMode::Bsdf:
      return "bsdf";
    case LightingMode::MedianCut:
      return "median_cut";
    case LightingMode::MedianCutAll:
      return "median_cut_all";
  }
  return "?";
}

RenderRequest parse_render_request(const Json& body, const RenderLimits& limits) {
  if (!body.is_object()) throw ApiError(ErrorCode::InvalidJson, "the request body must be a JSON object");
  reject_unknown_fields(body, {"envmap", "scene", "lighting", "width", "height", "spp", "max_depth", "seed"});
  RenderRequest r;
  r.envmap = json_string(body, "envmap", std::nullopt);
  if (r.envmap.empty()) throw invalid_field("envmap", "must not be empty");
  r.scene = parse_scene(object_member(body, "scene", ""), limits, r.preset);
  r.lighting = parse_lighting(object_member(body, "lighting", ""), limits);
  const RenderSettings d;
  r.settings.width = bounded_int(body, "width", d.width, 1, limits.max_width);
  r.settings.height = bounded_int(body, "height", d.height, 1, limits.max_height);
  r.settings.spp = bounded_int(body, "spp", d.spp, 1, limits.max_spp);
  r.settings.max_depth = bounded_int(body, "max_depth", d.max_depth, 0, limits.max_depth);
  r.settings.mesh_limits.max_triangles = limits.max_mesh_triangles;
  r.settings.seed = uint64_t(json_int(body, "seed", int64_t(d.seed), 0, std::numeric_limits<int64_t>::max()));
  return r;
}

}  // namespace lp::api
