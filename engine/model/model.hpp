#pragma once
// A model ready to render: the triangles of every mesh the scene places, in world space, in one set of
// flat arrays (one Embree triangle geometry: `positions` as RTC_FORMAT_FLOAT3 vertices, `indices` as
// RTC_FORMAT_UINT3 triangles), per-vertex attributes to interpolate at a hit's barycentrics, and a
// material per triangle. Materials are glTF's metallic-roughness model; OBJ/MTL files are mapped onto it.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/limits.hpp"
#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model_files.hpp"
#include "engine/model/model_memory.hpp"
#include "engine/texture/texture.hpp"
#include "engine/texture/texture_transform.hpp"
#include "engine/texture/wrap_mode.hpp"

namespace lp {

// Limits checked while a model loads, before what they bound is allocated (lp::Error TooLarge).
struct ModelLimits {
  int64_t max_triangles = limits::kDefaultMaxMeshTriangles;  // after the node hierarchy's instancing
  int64_t max_file_bytes = limits::kMaxMeshFileBytes;        // the model and every file it refers to
  int64_t max_texture_pixels = limits::kDefaultMaxTexturePixels;
  int64_t max_total_texture_pixels = limits::kDefaultMaxModelTexturePixels;
  ModelReserve reserve;  // none: memory is not counted
};

// A texture as a material uses it: the shared texels, the sampler's wrap modes and the texture
// transform to apply to the vertex UVs before the lookup.
struct TextureBinding {
  std::shared_ptr<const Texture> texture;
  TextureSampler sampler;
  TextureTransform transform;
  int tex_coord = 0;  // the texture coordinate set: 0 (Model::uvs) or 1 (Model::uvs1)

  Rgba sample(Point2 uv, float level) const { return texture->sample(transform.apply(uv), level, sampler); }
  // Over a footprint in the vertex UVs: the transform scales and turns its axes as it does the UVs.
  Rgba sample(Point2 uv, const UvFootprint& footprint, float max_anisotropy) const {
    const UvFootprint f{transform.apply_to_vector(footprint.a), transform.apply_to_vector(footprint.b)};
    return texture->sample(transform.apply(uv), f, max_anisotropy, sampler);
  }
};

// A glTF material's KHR_materials_ior, _specular, _transmission, _volume, _clearcoat and _sheen
// parameters (engine/bsdf/bsdf_gltf_pbr.hpp shades them). A texture, where present, multiplies its
// factor through the channel named beside it. Defaults are the extensions' own.
struct MaterialLobes {
  float ior = 1.5f;  // KHR_materials_ior
  // KHR_materials_specular
  float specular_factor = 1;
  std::optional<TextureBinding> specular;  // linear, A
  Rgb specular_color_factor{1, 1, 1};
  std::optional<TextureBinding> specular_color;  // sRGB-decoded, RGB
  // KHR_materials_transmission
  float transmission_factor = 0;
  std::optional<TextureBinding> transmission;  // linear, R
  // KHR_materials_volume: thickness 0 is a thin wall; above, the mesh encloses a volume that absorbs
  // 1 - attenuationColor over attenuationDistance (infinite: nothing).
  float thickness_factor = 0;
  std::optional<TextureBinding> thickness;  // linear, G
  float attenuation_distance = std::numeric_limits<float>::infinity();
  Rgb attenuation_color{1, 1, 1};
  // KHR_materials_clearcoat
  float clearcoat_factor = 0;
  std::optional<TextureBinding> clearcoat;  // linear, R
  float clearcoat_roughness_factor = 0;
  std::optional<TextureBinding> clearcoat_roughness;  // linear, G
  std::optional<TextureBinding> clearcoat_normal;     // linear, tangent space, as normalTexture
  float clearcoat_normal_scale = 1;
  // KHR_materials_sheen
  Rgb sheen_color_factor{0, 0, 0};
  std::optional<TextureBinding> sheen_color;  // sRGB-decoded, RGB
  float sheen_roughness_factor = 0;
  std::optional<TextureBinding> sheen_roughness;  // linear, A

  // The absorption coefficient inside the volume, per unit length: -ln(attenuationColor) /
  // attenuationDistance per channel (0 without absorption).
  Rgb absorption() const;
  // Every texture, for counting memory.
  std::array<const std::optional<TextureBinding>*, 9> textures() const {
    return {&specular,         &specular_color, &transmission,   &thickness, &clearcoat, &clearcoat_roughness,
            &clearcoat_normal, &sheen_color,    &sheen_roughness};
  }
};

// How a material covers its surface (glTF alphaMode). Alpha is base colour factor x texture x COLOR_0.
enum class AlphaMode { Opaque, Mask, Blend };

// glTF 2.0 metallic-roughness. A texture, where present, multiplies its factor.
struct ModelMaterial {
  std::string name;
  Rgba base_color_factor;                    // linear RGBA
  std::optional<TextureBinding> base_color;  // sRGB-decoded
  float metallic_factor = 1;
  float roughness_factor = 1;                        // perceptual roughness: GGX alpha = roughness^2
  std::optional<TextureBinding> metallic_roughness;  // linear: B = metallic, G = roughness
  std::optional<TextureBinding> normal;  // linear, tangent space: n = (2 * rgb - 1) * (scale, scale, 1)
  float normal_scale = 1;
  Rgb emissive_factor{0, 0, 0};
  std::optional<TextureBinding> emissive;  // sRGB-decoded
  std::optional<MaterialLobes> lobes;      // when the material uses one of MaterialLobes' extensions

  // Coverage, sidedness and emission strength (glTF alphaMode, alphaCutoff, doubleSided,
  // KHR_materials_emissive_strength). Opaque ignores alpha; Mask keeps alpha >= alpha_cutoff; Blend
  // keeps a hit with probability alpha. A single-sided material's back faces are not seen by camera rays.
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = true;  // glTF's default false is set by its loader; OBJ/MTL states no side
  float emissive_strength = 1;
  bool needs_hit_filter() const { return alpha_mode != AlphaMode::Opaque || !double_sided; }

  // Every texture the material uses, its lobes' included.
  std::vector<const std::optional<TextureBinding>*> bindings() const {
    std::vector<const std::optional<TextureBinding>*> out{&base_color, &metallic_roughness, &normal,
                                                          &emissive};
    if (lobes)
      for (const auto* b : lobes->textures()) out.push_back(b);
    return out;
  }
};

// Tangent direction (unit, perpendicular to the normal) and handedness: the bitangent is
// cross(normal, tangent) * w, pointing up the image (towards smaller v), as glTF defines it.
struct Tangent {
  Vec3 direction{1, 0, 0};
  float w = 1;
};

// A camera the file places (glTF), in the world frame.
struct ModelCamera {
  std::string name;
  uint32_t index = 0;       // in the file's cameras
  bool perspective = true;  // false: orthographic (listed, not rendered)
  Vec3 position;
  Vec3 forward{0, 1, 0};  // unit
  Vec3 up{0, 0, 1};       // unit
  float yfov_deg = 0;     // the vertical field of view of a perspective camera
};

// What the model's file says beyond the triangles it makes, for its description (model_info.hpp).
struct ModelSource {
  struct Material {
    std::vector<std::string> extensions;  // the glTF extensions the material carries
  };
  struct Camera {
    std::string name;
    std::string type;  // "perspective" or "orthographic"
  };
  int64_t meshes = 0;               // glTF meshes the scene places; OBJ objects and groups
  std::vector<Material> materials;  // per glTF material, in the order of Model::materials
  std::vector<Camera> cameras;      // glTF cameras, by index
  std::vector<std::string> extensions_used;
  std::vector<std::string> warnings;  // what the file holds that is ignored, each saying where
};

struct Model {
  std::vector<Vec3> positions;  // world space
  std::vector<Vec3> normals;    // per vertex, unit
  std::vector<Point2> uvs;      // TEXCOORD_0 ((0, 0) where a mesh has none)
  std::vector<Tangent> tangents;
  // Optional per-vertex attributes, empty unless some part has them (others then get the defaults).
  std::vector<Rgba> colors;                  // COLOR_0 (white where a part has none)
  std::vector<Point2> uvs1;                  // TEXCOORD_1 ((0, 0) where a part has none)
  std::vector<uint32_t> indices;             // three per triangle, counter-clockwise seen from the front
  std::vector<uint32_t> triangle_materials;  // per triangle, an index into `materials`
  std::vector<ModelMaterial> materials;
  // False: in the world frame (a glTF, converted as model_frame.hpp says). True: in its file's own
  // coordinates, whose up axis the file does not state (OBJ); placing it in a scene says which it is.
  bool up_axis_unstated = false;
  std::vector<ModelCamera> cameras;  // one per node holding a camera, in the scene's node order
  // The files it was read from, the model file first (none for a model from memory): a copy kept in
  // memory is stale once one of them has changed.
  std::vector<FileStamp> files;
  ModelSource source;

  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return indices.size() / 3; }
  // Bytes of the geometry arrays plus the textures the materials hold (shared ones counted once).
  int64_t memory_bytes() const;
};

}  // namespace lp
