// The scenes named in the API. All are z-up, seen from the -y side.
#include "engine/fresnel/metals.hpp"
#include "engine/render/scene_desc.hpp"
#include "engine/render/textured_preset.hpp"

namespace lp::render {
namespace {

Camera front_camera() {
  return {{0, -4, 0}, {0, 0, 0}, {0, 0, 1}, 40};
}

// The classic light-probe test: a diffuse sphere of albedo 0.8.
SceneDesc sphere_scene() {
  return {front_camera(), {{SphereObject{{0, 0, 0}, 1}, DiffuseMaterial{{0.8f, 0.8f, 0.8f}}}}};
}

// A sphere of albedo 0.5 alone: in a constant map of radiance 1 every pixel on it is 0.5.
SceneDesc furnace_scene() {
  return {front_camera(), {{SphereObject{{0, 0, 0}, 1}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}}}};
}

// Mirror, plastic, glass and rough gold spheres in a row on a diffuse plane.
SceneDesc materials_scene() {
  const ConductorPreset& gold = lookup_metal("gold");
  SceneDesc s;
  s.camera = {{0, -6.5f, 1.6f}, {0, 0, -0.1f}, {0, 0, 1}, 35};
  const float r = 0.5f, step = 1.15f;
  s.objects = {
      {SphereObject{{-1.5f * step, 0, 0}, r}, MirrorMaterial{{0.95f, 0.95f, 0.95f}}},
      {SphereObject{{-0.5f * step, 0, 0}, r}, PlasticMaterial{{0.7f, 0.08f, 0.06f}, 1.5f, 0.1f}},
      {SphereObject{{0.5f * step, 0, 0}, r}, DielectricMaterial{1.5f}},
      {SphereObject{{1.5f * step, 0, 0}, r}, ConductorMaterial{gold.eta_rgb(), gold.k_rgb(), 0.25f}},
      {PlaneObject{{0, 0, -r}, {0, 0, 1}}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}},
  };
  return s;
}

// A brick-textured, normal-mapped sphere on a checkerboard ground, seen from above the ground so that
// the far squares are small: the scene for comparing mipmaps and normal maps on and off.
SceneDesc textured_scene() {
  SceneDesc s;
  s.camera = {{0, -5, 1.2f}, {0, 0, -0.3f}, {0, 0, 1}, 45};
  MeshObject model;
  model.path = "textured";
  model.model = textured_preset_model();
  model.model_materials = true;
  s.objects = {{model, DiffuseMaterial{}}};
  return s;
}

}  // namespace

SceneDesc preset_scene(ScenePreset preset) {
  switch (preset) {
    case ScenePreset::Sphere:
      return sphere_scene();
    case ScenePreset::Materials:
      return materials_scene();
    case ScenePreset::Furnace:
      return furnace_scene();
    case ScenePreset::Textured:
      return textured_scene();
  }
  return sphere_scene();
}

std::optional<SceneDesc> scene_preset(std::string_view name) {
  const auto preset = parse_enum<ScenePreset>(name);
  if (!preset) return std::nullopt;
  return preset_scene(*preset);
}

}  // namespace lp::render
