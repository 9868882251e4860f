#include "engine/render/scene_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/validate.hpp"
#include "engine/model/model_loader.hpp"
#include "engine/render/mesh_transform.hpp"
#include "engine/render/placed_model.hpp"

namespace lp::render {
namespace {

const std::string kFitField = "scene.camera.fit", kGltfField = "scene.camera.gltf";

// Calls f(p) for every vertex of the mesh, placed in the world.
template <class F>
void for_each_placed_vertex(const MeshObject& mesh, F&& f) {
  const Mat4 frame = file_to_world(mesh, *mesh.model);
  for (Vec3 p : mesh.model->positions) f(transform_mesh_point(mesh, frame.point(p)));
}

// The farthest distance from `c` of the object's points.
float reach(const SceneObject& object, Vec3 c) {
  if (const auto* s = std::get_if<SphereObject>(&object.shape)) return length(s->center - c) + s->radius;
  float r = 0;
  if (const auto* m = std::get_if<MeshObject>(&object.shape))
    for_each_placed_vertex(*m, [&](Vec3 p) { r = std::max(r, length(p - c)); });
  return r;
}

bool framed(const SceneObject& object, size_t i, std::optional<uint32_t> only) {
  return !std::holds_alternative<PlaneObject>(object.shape) && (!only || *only == i);
}

Camera gltf_camera(const SceneDesc& scene, const GltfCameraChoice& choice, float fov_fallback) {
  const MeshObject* mesh = nullptr;
  for (size_t i = 0; i < scene.objects.size() && !mesh; ++i) {
    const auto* m = std::get_if<MeshObject>(&scene.objects[i].shape);
    if (m && (choice.object ? *choice.object == i : !m->model->cameras.empty())) mesh = m;
  }
  if (!mesh || mesh->model->cameras.empty())
    invalid_parameter(kGltfField, choice.object
                                      ? fmt::format("object {}'s model has no cameras", *choice.object)
                                      : "no mesh object's model has cameras");
  const auto& cameras = mesh->model->cameras;
  const auto found = std::find_if(cameras.begin(), cameras.end(), [&](const ModelCamera& c) {
    return choice.index ? c.index == *choice.index : c.name == choice.name;
  });
  if (found == cameras.end()) {
    std::string names;
    for (const ModelCamera& c : cameras)
      names += fmt::format("{}{} '{}'", names.empty() ? "" : ", ", c.index, c.name);
    invalid_parameter(
        kGltfField, choice.index
                        ? fmt::format("the model has no camera {} (it has {})", *choice.index, names)
                        : fmt::format("the model has no camera named '{}' (it has {})", choice.name, names));
  }
  if (!found->perspective)
    invalid_parameter(kGltfField,
                      fmt::format("camera {} '{}' is orthographic; only perspective cameras render",
                                  found->index, found->name));
  const Mat4 frame = file_to_world(*mesh, *mesh->model);
  Camera c;
  c.position = transform_mesh_point(*mesh, frame.point(found->position));
  c.look_at = c.position + rotate_mesh_direction(*mesh, frame.vector(found->forward));
  c.up = rotate_mesh_direction(*mesh, frame.vector(found->up));
  c.fov_deg = found->yfov_deg > 0 ? found->yfov_deg : fov_fallback;
  return c;
}

// Whether a sphere reaches into the cone around the camera's view holding the whole image.
bool in_view(const Camera& c, float aspect, Vec3 center, float radius) {
  const Vec3 d = center - c.position;
  const float distance = length(d);
  if (distance <= radius) return true;
  const float half_v = 0.5f * c.fov_deg * kPiF / 180;
  const float half_diagonal = std::atan(std::tan(half_v) * std::sqrt(1 + aspect * aspect));
  const float angle =
      std::acos(std::clamp(dot(d / distance, normalize(c.look_at - c.position)), -1.0f, 1.0f));
  return angle - std::asin(radius / distance) < half_diagonal;
}

bool sees_nothing(const SceneDesc& scene, const Camera& c, float aspect) {
  for (const SceneObject& o : scene.objects) {
    if (std::holds_alternative<PlaneObject>(o.shape)) return false;
    if (const auto* m = std::get_if<MeshObject>(&o.shape); m && !m->model) return false;
    if (const auto* s = std::get_if<SphereObject>(&o.shape)) {
      if (in_view(c, aspect, s->center, s->radius)) return false;
      continue;
    }
    const Bounds b = object_bounds(o);
    if (!b.empty() && in_view(c, aspect, b.center(), 0.5f * length(b.max - b.min))) return false;
  }
  return !scene.objects.empty();
}

std::vector<std::string> inside_warnings(const SceneDesc& scene, Vec3 eye) {
  std::vector<std::string> out;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const auto* mesh = std::get_if<MeshObject>(&o.shape);
    const auto* sphere = std::get_if<SphereObject>(&o.shape);
    if (sphere && length(eye - sphere->center) < sphere->radius)
      out.push_back(fmt::format("the camera is inside scene.objects[{}] (a sphere)", i));
    if (mesh && mesh->model && object_bounds(o).contains(eye))
      out.push_back(
          fmt::format("the camera is inside the bounds of scene.objects[{}] ({}): it may see the model "
                      "from within or not at all",
                      i, mesh->path.filename().string()));
  }
  return out;
}

}  // namespace

Bounds object_bounds(const SceneObject& object) {
  Bounds b;
  if (const auto* s = std::get_if<SphereObject>(&object.shape)) {
    const Vec3 r{s->radius, s->radius, s->radius};
    b.extend(s->center - r);
    b.extend(s->center + r);
  } else if (const auto* m = std::get_if<MeshObject>(&object.shape); m && m->model) {
    for_each_placed_vertex(*m, [&](Vec3 p) { b.extend(p); });
  }
  return b;
}

BoundingSphere framing_sphere(const SceneDesc& scene, std::optional<uint32_t> object) {
  Bounds all;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (framed(scene.objects[i], i, object)) all.extend(object_bounds(scene.objects[i]));
  if (all.empty()) return {};
  BoundingSphere s{all.center(), 0};
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (framed(scene.objects[i], i, object)) s.radius = std::max(s.radius, reach(scene.objects[i], s.center));
  return s;
}

Camera fit_camera(const CameraFit& fit, const BoundingSphere& sphere, float fov_deg, float aspect) {
  const float half_v = 0.5f * fov_deg * kPiF / 180;
  const float half = std::min(half_v, std::atan(std::tan(half_v) * aspect));
  const float distance = std::max(sphere.radius, 1e-3f) * fit.margin / std::sin(half);
  const float az = fit.azimuth_deg * kPiF / 180, el = fit.elevation_deg * kPiF / 180;
  const Vec3 towards_eye{std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)};
  Camera c;
  c.position = sphere.center + towards_eye * distance;
  c.look_at = sphere.center;
  c.up = {0, 0, 1};
  c.fov_deg = fov_deg;
  return c;
}

Camera resolve_camera(const SceneDesc& scene, float aspect) {
  const Camera& asked = scene.camera;
  Camera camera = asked;
  if (asked.fit) {
    const BoundingSphere sphere = framing_sphere(scene, asked.fit->object);
    if (!(sphere.radius > 0))
      invalid_parameter(kFitField, asked.fit->object
                                       ? fmt::format("object {} has no extent to frame", *asked.fit->object)
                                       : "the scene has no sphere or mesh to frame");
    camera = fit_camera(*asked.fit, sphere, asked.fov_deg, aspect);
  } else if (asked.gltf) {
    camera = gltf_camera(scene, *asked.gltf, asked.fov_deg);
  }
  camera.fit.reset();
  camera.gltf.reset();
  return camera;
}

SceneView resolve_view(const SceneDesc& scene, float aspect) {
  SceneView view;
  view.camera = resolve_camera(scene, aspect);
  view.warnings = inside_warnings(scene, view.camera.position);
  if (sees_nothing(scene, view.camera, aspect))
    view.warnings.push_back(
        "the camera's view holds none of the scene's objects: the image shows only the map");
  return view;
}

void resolve_grounds(SceneDesc& scene) {
  std::optional<float> lowest;
  for (SceneObject& o : scene.objects) {
    if (!o.ground) continue;
    if (!o.ground->height && !lowest) {
      Bounds all;
      for (const SceneObject& other : scene.objects)
        if (!std::holds_alternative<PlaneObject>(other.shape)) all.extend(object_bounds(other));
      lowest = all.empty() ? 0.0f : all.min.z;
    }
    o.shape = PlaneObject{{0, 0, o.ground->height.value_or(*lowest)}, {0, 0, 1}};
  }
}

bool needs_models(const SceneDesc& scene) {
  return scene.camera.fit || scene.camera.gltf ||
         std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const SceneObject& o) { return o.ground && !o.ground->height; });
}

void load_missing_models(SceneDesc& scene, const MeshLimits& limits) {
  for (SceneObject& o : scene.objects) {
    auto* mesh = std::get_if<MeshObject>(&o.shape);
    if (!mesh || mesh->model) continue;
    mesh->model = std::make_shared<const Model>(load_model(mesh->path, model_limits(limits)));
  }
}

}  // namespace lp::render
