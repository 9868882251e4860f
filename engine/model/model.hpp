#pragma once
// A model ready to render: the triangles of every mesh the scene places, in world space, in one set of
// flat arrays (one Embree triangle geometry: `positions` as RTC_FORMAT_FLOAT3 vertices, `indices` as
// RTC_FORMAT_UINT3 triangles), per-vertex attributes to interpolate at a hit's barycentrics, and a
// material per triangle. Materials are glTF's metallic-roughness model; OBJ/MTL files are mapped onto it.
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/limits.hpp"
#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"
#include "engine/model/model_files.hpp"
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
};

// A texture as a material uses it: the shared texels, the sampler's wrap modes and the texture
// transform to apply to the vertex UVs before the lookup.
struct TextureBinding {
  std::shared_ptr<const Texture> texture;
  TextureSampler sampler;
  TextureTransform transform;
  int tex_coord = 0;  // the texture coordinate set: 0 (Model::uvs) or 1 (Model::uvs1)

  Rgba sample(Point2 uv, float level) const { return texture->sample(transform.apply(uv), level, sampler); }
  // The mip level for a footprint `uv_width` wide in the vertex UVs: the transform's scale widens it.
  float level_for_footprint(float uv_width) const {
    return texture->level_for_footprint(uv_width *
                                        std::sqrt(std::abs(transform.scale.x * transform.scale.y)));
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

  // Coverage, sidedness and emission strength (glTF alphaMode, alphaCutoff, doubleSided,
  // KHR_materials_emissive_strength). Opaque ignores alpha; Mask keeps alpha >= alpha_cutoff; Blend
  // keeps a hit with probability alpha. A single-sided material's back faces are not seen by camera rays.
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = true;  // glTF's default false is set by its loader; OBJ/MTL states no side
  float emissive_strength = 1;
  bool needs_hit_filter() const { return alpha_mode != AlphaMode::Opaque || !double_sided; }

  // The textures it holds, those absent included (null).
  std::vector<const std::optional<TextureBinding>*> bindings() const {
    return {&base_color, &metallic_roughness, &normal, &emissive};
  }
};

// Tangent direction (unit, perpendicular to the normal) and handedness: the bitangent is
// cross(normal, tangent) * w, pointing up the image (towards smaller v), as glTF defines it.
struct Tangent {
  Vec3 direction{1, 0, 0};
  float w = 1;
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
  // The files it was read from, the model file first (none for a model from memory): a copy kept in
  // memory is stale once one of them has changed.
  std::vector<FileStamp> files;

  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return indices.size() / 3; }
  // Bytes of the geometry arrays plus the textures the materials hold (shared ones counted once).
  int64_t memory_bytes() const;
};

}  // namespace lp
