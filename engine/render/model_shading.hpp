#pragma once
// A model's material at a hit: its textures filtered over the ray cone's footprint (the same for light
// and BSDF sampling), and the shading normal its normal map gives.
#include <optional>

#include "engine/model/model.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/ray_cone.hpp"

namespace lp::render {

struct TextureLookup {
  SurfaceFootprint footprint;                    // the ray cone's ellipse on the surface (world units)
  bool mipmaps = true;                           // false: level 0
  bool normal_maps = true;                       // false: the normal texture is ignored
  float max_anisotropy = kMaxTextureAnisotropy;  // 1: one probe at the level of the longest diameter
};

// A material's MaterialLobes at a hit, its textures applied.
struct SurfaceLobes {
  float ior = 1.5f;
  float specular = 1;
  Rgb specular_color{1, 1, 1};
  float transmission = 0;
  bool thin_walled = true;
  Rgb absorption;  // inside the volume, per unit length
  float clearcoat = 0;
  float clearcoat_roughness = 0;
  Vec3 clearcoat_normal;  // unit, world space, on the side of the hit's shading_normal
  Rgb sheen_color;
  float sheen_roughness = 0;
};

struct ModelSurface {
  Rgb base_color;
  float metallic = 0;
  float roughness = 1;  // perceptual
  Rgb emission;
  Vec3 shading_normal;  // unit, on the side of the hit's shading_normal
  std::optional<SurfaceLobes> lobes;
};

// A surface footprint in the hit triangle's texture coordinate set `tex_coord` (0 or 1): each
// diameter's change of u and v.
UvFootprint uv_footprint(const SurfaceHit& hit, const SurfaceFootprint& footprint, int tex_coord = 0);

ModelSurface model_surface(const ModelMaterial& material, const SurfaceHit& hit, const TextureLookup& lookup);

// The tangent-space normal a normal-map texel encodes, (2 rgb - 1) scaled in x and y. An 8-bit map
// cannot hold 0.5: components within one 8-bit step of 0 are read as 0, so a flat map (128, 128, 255)
// gives exactly (0, 0, 1) and renders like no map.
Vec3 decode_normal_texel(Rgb texel, float scale);

// The guard against shading normals that face away from the viewer: the normal is bent (not flipped)
// towards the geometric one until the mirror direction of `wo` about it lies above the geometric
// surface (Keller et al. 2017, "The Iray Light Transport Simulation and Rendering System", sec. A.3).
// Bending keeps the shading continuous where flipping would jump. All vectors unit, world space, `ng`
// and `ns` on the side of `wo` (dot(wo, ng) > 0). A normal that needs no bend is returned unchanged.
Vec3 bend_shading_normal(Vec3 ns, Vec3 ng, Vec3 wo);

}  // namespace lp::render
