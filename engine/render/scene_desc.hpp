#pragma once
// What to render, as plain data: the contract between the request parser (api/) and the renderer.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/vec3.hpp"

namespace lp::render {

struct DiffuseMaterial { Rgb albedo{0.8f, 0.8f, 0.8f}; };
struct MirrorMaterial { Rgb color{1, 1, 1}; };
struct DielectricMaterial { float ior = 1.5f; };
struct PlasticMaterial { Rgb albedo{0.5f, 0.5f, 0.5f}; float ior = 1.5f; float roughness = 0.1f; };
struct ConductorMaterial {
  Rgb eta{0.2f, 0.4f, 1.4f};  // filled from a preset (e.g. "gold") by the parser, or given
  Rgb k{3.6f, 2.4f, 1.8f};
  float roughness = 0.0f;     // GGX alpha; 0 = smooth
};
using Material = std::variant<DiffuseMaterial, MirrorMaterial, DielectricMaterial, PlasticMaterial, ConductorMaterial>;

struct SphereObject { Vec3 center; float radius = 1; };
struct PlaneObject { Vec3 point; Vec3 normal{0, 0, 1}; };
struct MeshObject {
  std::filesystem::path path;  // already resolved and checked to be inside the data dir
  Vec3 translate;
  float scale = 1;
  Vec3 rotate_deg;             // rotations about x, then y, then z
};
struct SceneObject {
  std::variant<SphereObject, PlaneObject, MeshObject> shape;
  Material material;
};

struct Camera {
  Vec3 position{0, -4, 0};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 0, 1};
  float fov_deg = 40;
};

struct SceneDesc {
  Camera camera;
  std::vector<SceneObject> objects;
};

enum class LightingMode { EnvMap, Uniform, Bsdf, MedianCut, MedianCutAll };

struct Lighting {
  LightingMode mode = LightingMode::EnvMap;
  int lights = 64;            // median-cut light count
  float rotation_deg = 0;     // about z
  float intensity = 1;
  bool visible = true;        // the camera sees the map
};

// Limits on mesh files, checked while loading (lp::Error TooLarge when over).
struct MeshLimits {
  int64_t max_triangles = 2'000'000;
  int64_t max_file_bytes = int64_t{256} << 20;
};

struct RenderSettings {
  int width = 256, height = 256;
  int spp = 64;
  int max_depth = 8;      // bounces: 0 = only what the camera sees directly, 1 = direct lighting, ...
  uint64_t seed = 1;
  MeshLimits mesh_limits;
};

// Presets named in the API: "sphere", "materials", "furnace".
std::optional<SceneDesc> scene_preset(const std::string& name);

}  // namespace lp::render
