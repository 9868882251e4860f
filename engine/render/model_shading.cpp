#include "engine/render/model_shading.hpp"

#include <algorithm>
#include <cmath>

namespace lp::render {
namespace {

// Smallest height of the bent mirror direction above the geometric surface.
inline constexpr float kMinReflectionHeight = 0.01f;

Rgba lookup_texture(const TextureBinding& binding, const SurfaceHit& hit, const TextureLookup& lookup) {
  const bool second = binding.tex_coord == 1;
  const Point2 uv = second ? hit.uv1 : hit.uv;
  if (!lookup.mipmaps) return binding.sample(uv, 0.0f);
  return binding.sample(uv, uv_footprint(hit, lookup.footprint, binding.tex_coord), lookup.max_anisotropy);
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

// A texture's channel times its factor, or the factor alone.
float textured(float factor, const std::optional<TextureBinding>& t, float Rgba::*channel,
               const SurfaceHit& hit, const TextureLookup& lookup) {
  return t ? factor * (lookup_texture(*t, hit, lookup).*channel) : factor;
}

Rgb textured(Rgb factor, const std::optional<TextureBinding>& t, const SurfaceHit& hit,
             const TextureLookup& lookup) {
  if (!t) return factor;
  const Rgb c = lookup_texture(*t, hit, lookup).rgb();
  return {factor.x * c.x, factor.y * c.y, factor.z * c.z};
}

SurfaceLobes surface_lobes(const MaterialLobes& m, const SurfaceHit& hit, const TextureLookup& lookup) {
  constexpr auto kR = &Rgba::r, kG = &Rgba::g, kA = &Rgba::a;
  SurfaceLobes s;
  s.ior = m.ior;
  s.specular = textured(m.specular_factor, m.specular, kA, hit, lookup);
  s.specular_color = textured(m.specular_color_factor, m.specular_color, hit, lookup);
  s.transmission = textured(m.transmission_factor, m.transmission, kR, hit, lookup);
  s.thin_walled = !(textured(m.thickness_factor, m.thickness, kG, hit, lookup) > 0);
  s.absorption = m.absorption();
  s.clearcoat = textured(m.clearcoat_factor, m.clearcoat, kR, hit, lookup);
  s.clearcoat_roughness = textured(m.clearcoat_roughness_factor, m.clearcoat_roughness, kG, hit, lookup);
  s.clearcoat_normal = m.clearcoat_normal && lookup.normal_maps
                           ? mapped_normal(*m.clearcoat_normal, m.clearcoat_normal_scale, hit, lookup)
                           : hit.shading_normal;
  s.sheen_color = textured(m.sheen_color_factor, m.sheen_color, hit, lookup);
  s.sheen_roughness = textured(m.sheen_roughness_factor, m.sheen_roughness, kA, hit, lookup);
  return s;
}

}  // namespace

Vec3 decode_normal_texel(Rgb texel, float scale) {
  const float x = snap_to_zero(2.0f * texel.x - 1.0f), y = snap_to_zero(2.0f * texel.y - 1.0f);
  const float z = 2.0f * texel.z - 1.0f;
  return {x * scale, y * scale, z};
}

UvFootprint uv_footprint(const SurfaceHit& hit, const SurfaceFootprint& f, int tex_coord) {
  const Vec3 du = tex_coord == 1 ? hit.du1_dp : hit.du_dp, dv = tex_coord == 1 ? hit.dv1_dp : hit.dv_dp;
  return {{dot(du, f.across), dot(dv, f.across)}, {dot(du, f.along), dot(dv, f.along)}};
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
  if (m.lobes) s.lobes = surface_lobes(*m.lobes, hit, lookup);
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
