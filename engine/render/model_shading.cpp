#include "engine/render/model_shading.hpp"

#include <algorithm>
#include <cmath>

namespace lp::render {
namespace {

// Smallest height of the bent mirror direction above the geometric surface.
inline constexpr float kMinReflectionHeight = 0.01f;

float texture_level(const TextureBinding& binding, const TextureLookup& lookup, float uv_density) {
  if (!lookup.mipmaps) return 0.0f;
  const Point2 scale = binding.transform.scale;
  const float uv_width = lookup.surface_width * uv_density * std::sqrt(std::abs(scale.x * scale.y));
  return binding.texture->level_for_footprint(uv_width);
}

Rgba lookup_texture(const TextureBinding& binding, const SurfaceHit& hit, const TextureLookup& lookup) {
  if (binding.tex_coord == 1) return binding.sample(hit.uv1, texture_level(binding, lookup, hit.uv1_density));
  return binding.sample(hit.uv, texture_level(binding, lookup, hit.uv_density));
}

float snap_to_zero(float c) {
  return std::abs(c) <= 1.0f / 255.0f + 1e-6f ? 0.0f : c;
}

Vec3 mapped_normal(const TextureBinding& map, float scale, const SurfaceHit& hit,
                   const TextureLookup& lookup) {
  const Vec3 local = decode_normal_texel(lookup_texture(map, hit, lookup).rgb(), scale);
  const Vec3& n = hit.shading_normal;
  const Vec3 t = hit.tangent.direction;
  const Vec3 b = cross(n, t) * hit.tangent.w;
  const Vec3 world = t * local.x + b * local.y + n * local.z;
  return dot(world, world) > 0 ? normalize(world) : n;
}

}  // namespace

Vec3 decode_normal_texel(Rgb texel, float scale) {
  const float x = snap_to_zero(2.0f * texel.x - 1.0f), y = snap_to_zero(2.0f * texel.y - 1.0f);
  const float z = 2.0f * texel.z - 1.0f;
  return {x * scale, y * scale, z};
}

ModelSurface model_surface(const ModelMaterial& m, const SurfaceHit& hit, const TextureLookup& lookup) {
  ModelSurface s;
  s.base_color = m.base_color_factor.rgb();
  if (m.base_color) {
    const Rgb t = lookup_texture(*m.base_color, hit, lookup).rgb();
    s.base_color = {s.base_color.x * t.x, s.base_color.y * t.y, s.base_color.z * t.z};
  }
  s.base_color = {s.base_color.x * hit.color.r, s.base_color.y * hit.color.g, s.base_color.z * hit.color.b};
  s.metallic = m.metallic_factor;
  s.roughness = m.roughness_factor;
  if (m.metallic_roughness) {
    const Rgba t = lookup_texture(*m.metallic_roughness, hit, lookup);
    s.metallic *= t.b;
    s.roughness *= t.g;
  }
  s.emission = m.emissive_factor;
  if (m.emissive) {
    const Rgb t = lookup_texture(*m.emissive, hit, lookup).rgb();
    s.emission = {s.emission.x * t.x, s.emission.y * t.y, s.emission.z * t.z};
  }
  s.emission = s.emission * m.emissive_strength;
  s.shading_normal = m.normal && lookup.normal_maps ? mapped_normal(*m.normal, m.normal_scale, hit, lookup)
                                                    : hit.shading_normal;
  return s;
}

Vec3 bend_shading_normal(Vec3 ns, Vec3 ng, Vec3 wo) {
  const Vec3 r = 2.0f * dot(wo, ns) * ns - wo;
  const float height = dot(r, ng);
  // At grazing views the floor drops to the view's own height, which an unperturbed normal keeps.
  const float floor = std::min(kMinReflectionHeight, dot(wo, ng));
  if (height >= floor - 1e-6f) return ns;
  const Vec3 bent_r = normalize(r + ng * (floor - height));
  return normalize(wo + bent_r);
}

}  // namespace lp::render
