#pragma once
// What to render, as plain data: the contract between the request parser (api/) and the renderer.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/core/limits.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model.hpp"
#include "engine/model/model_frame.hpp"
#include "engine/sun/sun_params.hpp"

namespace lp::render {

// Every parameter struct's validate(prefix) throws lp::Error(InvalidArgument) naming the first field out of
// its range (engine/core/limits.hpp) by its path under `prefix`, e.g. "scene.objects[2].material.ior".
struct DiffuseMaterial {
  Rgb albedo{0.8f, 0.8f, 0.8f};
  void validate(const std::string& prefix) const;
};
struct MirrorMaterial {
  Rgb color{1, 1, 1};
  void validate(const std::string& prefix) const;
};
struct DielectricMaterial {
  float ior = 1.5f;
  float roughness = 0.0f;  // GGX alpha; 0 = smooth glass, above it frosted
  void validate(const std::string& prefix) const;
};
struct PlasticMaterial {
  Rgb albedo{0.5f, 0.5f, 0.5f};
  float ior = 1.5f;
  float roughness = 0.1f;
  void validate(const std::string& prefix) const;
};
struct ConductorMaterial {
  Rgb eta{0.2f, 0.4f, 1.4f};  // filled from a preset (e.g. "gold") by the parser, or given
  Rgb k{3.6f, 2.4f, 1.8f};
  float roughness = 0.0f;  // GGX alpha; 0 = smooth
  void validate(const std::string& prefix) const;
};
using Material =
    std::variant<DiffuseMaterial, MirrorMaterial, DielectricMaterial, PlasticMaterial, ConductorMaterial>;

struct SphereObject {
  Vec3 center;
  float radius = 1;
  void validate(const std::string& prefix) const;
};
struct PlaneObject {
  Vec3 point;
  Vec3 normal{0, 0, 1};  // any length but 0
  void validate(const std::string& prefix) const;
};
struct MeshObject {
  std::filesystem::path path;  // already resolved and checked to be inside the data dir
  Vec3 translate;
  float scale = 1;
  Vec3 rotate_deg;  // rotations about x, then y, then z
  // The model already loaded from `path` (in its file's space, before the transform above), or null:
  // the renderer then loads it. .gltf, .glb and .obj files go through lp::load_model.
  std::shared_ptr<const Model> model;
  // True: the model's own materials (with their textures); false: the object's `material` overrides
  // them everywhere (a request that names a material).
  bool model_materials = false;
  // The up axis of a model file that states none (OBJ), turned to the world's +z before the transform;
  // kDefaultUpAxis when not given. A glTF is y-up by its specification: giving z for one is refused.
  std::optional<UpAxis> up_axis;
  void validate(const std::string& prefix) const;
};
// A horizontal ground: a plane facing +z at `height`, or, when none is given, at the lowest z of the
// scene's bounded objects (resolve_ground, once the models are loaded). A shadow catcher is invisible to
// the camera: where the camera sees it, it shows what lies behind it (the background) darkened by the
// shadows the other objects cast on it, plus the objects' light it reflects (Integrator::shadow_catcher),
// and its alpha is that shadow's opacity. Rays that have bounced see it as a surface of its material.
struct Ground {
  std::optional<float> height;
  bool shadow_catcher = false;
};

struct SceneObject {
  std::variant<SphereObject, PlaneObject, MeshObject> shape;
  Material material;
  // Set for a ground, whose shape is then a PlaneObject with normal +z.
  std::optional<Ground> ground{};
  void validate(const std::string& prefix) const;
};

// A camera that frames the bounding sphere of the scene's bounded objects (spheres and meshes; planes
// are unbounded), or of one of them: it looks at the sphere's centre from the direction `azimuth_deg`
// about +z (0: from the front, -y; 90: from +x) and `elevation_deg` above the horizon, with +z up, at the
// distance where the sphere's radius times `margin` fills the smaller of the two fields of view.
struct CameraFit {
  std::optional<uint32_t> object;  // an index into the scene's objects; all of them when absent
  float azimuth_deg = 0;
  float elevation_deg = 15;
  float margin = 1.05f;
  void validate(const std::string& prefix) const;
};

// A perspective camera of a glTF model, by its index in the file's `cameras` or by its name.
struct GltfCameraChoice {
  std::optional<uint32_t>
      object;  // the mesh object holding it; the first whose model has cameras when absent
  std::optional<uint32_t> index;
  std::string name;  // used when index is absent
};

struct Camera {
  Vec3 position{0, -4, 0};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 0, 1};
  float fov_deg = 40;
  // Either replaces position, look_at and up (and, for a glTF camera, fov_deg) once the models are
  // loaded (camera_fit.hpp).
  std::optional<CameraFit> fit{};
  std::optional<GltfCameraChoice> gltf{};
  void validate(const std::string& prefix) const;  // also: look_at away from position, up not along the view
};

struct SceneDesc {
  Camera camera;
  std::vector<SceneObject> objects;
  void validate(const std::string& prefix) const;
};

enum class LightingMode { EnvMap, Uniform, Bsdf, MedianCut, MedianCutAll };
constexpr auto enum_entries(LightingMode) {
  return std::to_array<EnumEntry<LightingMode>>({{LightingMode::EnvMap, "envmap"},
                                                 {LightingMode::Uniform, "uniform"},
                                                 {LightingMode::Bsdf, "bsdf"},
                                                 {LightingMode::MedianCut, "median_cut"},
                                                 {LightingMode::MedianCutAll, "median_cut_all"}});
}

// Whether an envmap render takes the map's sun out as a light of its own (engine/render/sun_light.hpp).
enum class SunMode { None, Extract };
constexpr auto enum_entries(SunMode) {
  return std::to_array<EnumEntry<SunMode>>({{SunMode::None, "none"}, {SunMode::Extract, "extract"}});
}

struct Lighting {
  LightingMode mode = LightingMode::EnvMap;
  int lights = 64;         // median-cut light count
  float rotation_deg = 0;  // about z
  float intensity = 1;
  bool visible = true;  // the camera sees the map
  // extract (with mode envmap only): the map's sun becomes a light of its own.
  SunMode sun = SunMode::None;
  SunParams sun_parameters;  // what counts as the sun there
  // The widest importance grid (env_light.hpp): a wider map is sampled on its first coarser level
  // that fits. Not a request field: the engine's trade between sampling memory and fidelity.
  int importance_max_width = limits::kDefaultImportanceMaxWidth;
  // Light samples from the map's MIS-compensated distribution (envmap.hpp, SamplerWeights). Not a request
  // field either: it only lowers the noise; off, for comparing the two.
  bool mis_compensation = true;
  void validate(const std::string& prefix) const;
};

// Limits on mesh files, checked while loading (lp::Error TooLarge when over).
struct MeshLimits {
  int64_t max_triangles = limits::kDefaultMaxMeshTriangles;
  int64_t max_file_bytes = limits::kMaxMeshFileBytes;
};

// How a render shares its samples among pixels: the same number everywhere, or in proportion to each
// pixel's noise (Renderer::render_adaptive_pass), `spp` being the mean.
enum class SamplingMode { Uniform, Adaptive };
constexpr auto enum_entries(SamplingMode) {
  return std::to_array<EnumEntry<SamplingMode>>(
      {{SamplingMode::Uniform, "uniform"}, {SamplingMode::Adaptive, "adaptive"}});
}

// What escaping camera rays see: the map (as Lighting::visible says), nothing (black, alpha 0), or a
// colour. The map lights the scene in every case.
enum class BackgroundMode { Map, Transparent, Color };
constexpr auto enum_entries(BackgroundMode) {
  return std::to_array<EnumEntry<BackgroundMode>>({{BackgroundMode::Map, "map"},
                                                   {BackgroundMode::Transparent, "transparent"},
                                                   {BackgroundMode::Color, "color"}});
}
struct Background {
  BackgroundMode mode = BackgroundMode::Map;
  Rgb color{};  // linear, with mode Color
  bool operator==(const Background&) const = default;
};

// The passes a render accumulates beside its colour, with the same samples (film.hpp):
//   albedo: the directional albedo of the first hit with a non-delta lobe (the weight f cos / pdf of its
//           BSDF sample, whose mean is that albedo; through mirrors and smooth glass, times their
//           colour); 0 where the camera ray escapes;
//   normal: the world shading normal at the first hit (facing the camera); 0 where it escapes;
//   depth:  the distance from the camera to the first hit, the mean over the samples that hit; +inf
//           where no sample hit;
//   alpha:  the coverage of camera rays: 1 for a hit, 0 for an escape, a shadow catcher's shadow
//           opacity where the camera sees the catcher.
enum class AuxPass { Albedo, Normal, Depth, Alpha };
constexpr auto enum_entries(AuxPass) {
  return std::to_array<EnumEntry<AuxPass>>({{AuxPass::Albedo, "albedo"},
                                            {AuxPass::Normal, "normal"},
                                            {AuxPass::Depth, "depth"},
                                            {AuxPass::Alpha, "alpha"}});
}
// A set of AuxPass, and where each pass's channels lie among the film's auxiliary channels.
class PassSet {
 public:
  PassSet() = default;
  PassSet(std::initializer_list<AuxPass> passes) {
    for (AuxPass p : passes) add(p);
  }
  void add(AuxPass p) { bits_ |= 1u << unsigned(p); }
  bool has(AuxPass p) const { return bits_ & (1u << unsigned(p)); }
  bool empty() const { return bits_ == 0; }
  // The passes of the set, in the order of AuxPass.
  std::vector<AuxPass> list() const {
    std::vector<AuxPass> out;
    for (const auto& e : enum_entries(AuxPass{}))
      if (has(e.value)) out.push_back(e.value);
    return out;
  }
  // The channels a pass holds in the film: 3 (albedo, normal), 2 (depth: the sum of distances and the
  // count of hits) or 1 (alpha).
  static int channels(AuxPass p) { return p == AuxPass::Depth ? 2 : p == AuxPass::Alpha ? 1 : 3; }
  int channels() const { return offset(AuxPass(kCount)); }
  // The first channel of pass p (which the set holds).
  int offset(AuxPass p) const {
    int at = 0;
    for (unsigned q = 0; q < unsigned(p); ++q)
      if (has(AuxPass(q))) at += channels(AuxPass(q));
    return at;
  }
  bool operator==(const PassSet&) const = default;
  // The set as bits (1 << AuxPass), as a partial film's bytes carry it; nullopt for unknown bits.
  unsigned bits() const { return bits_; }
  static std::optional<PassSet> from_bits(unsigned bits) {
    if (bits >> kCount) return std::nullopt;
    PassSet s;
    s.bits_ = bits;
    return s;
  }

 private:
  static constexpr unsigned kCount = 4;
  unsigned bits_ = 0;
};

struct RenderSettings {
  int width = 256, height = 256;
  int spp = 64;  // samples per pixel; their mean over the pixels with adaptive sampling
  SamplingMode sampling = SamplingMode::Uniform;
  int max_depth = 8;  // bounces: 0 = only what the camera sees directly, 1 = direct lighting, ...
  uint64_t seed = 1;
  MeshLimits mesh_limits;
  bool mipmaps = true;      // texture and map levels chosen by ray cones (else level 0 everywhere)
  bool normal_maps = true;  // tangent-space normal maps perturb the shading normal
  Background background;
  // A bound on the radiance of each indirect contribution (light that reached the first hit over at
  // least one more surface): one above it is scaled so its largest channel is the bound. Cycles'
  // "clamp indirect"; off when absent.
  std::optional<float> clamp;
  PassSet passes;
  // The longest texture footprint over its width before it is widened (1: isotropic levels, as wide
  // as the footprint is long). Not a request field: the engine's tests compare filters with it.
  float texture_anisotropy = kMaxTextureAnisotropy;
  void validate(const std::string& prefix) const;
};

// The built-in scenes: a diffuse sphere on a plane, a row of materials, a white furnace, a textured,
// normal-mapped model on a textured ground (textured_preset.hpp).
enum class ScenePreset { Sphere, Materials, Furnace, Textured };
constexpr auto enum_entries(ScenePreset) {
  return std::to_array<EnumEntry<ScenePreset>>({{ScenePreset::Sphere, "sphere"},
                                                {ScenePreset::Materials, "materials"},
                                                {ScenePreset::Furnace, "furnace"},
                                                {ScenePreset::Textured, "textured"}});
}

SceneDesc preset_scene(ScenePreset preset);
// The preset of this name, if there is one.
std::optional<SceneDesc> scene_preset(std::string_view name);

}  // namespace lp::render
