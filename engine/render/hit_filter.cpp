#include "engine/render/hit_filter.hpp"

#include <bit>

#include "engine/core/rng.hpp"

namespace lp::render {
namespace {

Point2 at_barycentric(const std::vector<Point2>& p, const uint32_t* tri, float u, float v) {
  const float w = 1.0f - u - v;
  return {p[tri[0]].x * w + p[tri[1]].x * u + p[tri[2]].x * v,
          p[tri[0]].y * w + p[tri[1]].y * u + p[tri[2]].y * v};
}

// Whether the hit is on the back of the triangle (against its counter-clockwise normal).
bool back_face(const Model& m, const uint32_t* tri, Vec3 direction) {
  const Vec3 a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
  return dot(cross(b - a, c - a), direction) > 0;
}

void filter(const RTCFilterFunctionNArguments* args) {
  const auto& model = *static_cast<const Model*>(args->geometryUserPtr);
  const bool camera = reinterpret_cast<const RayContext*>(args->context)->camera;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t triangle = RTCHitN_primID(args->hit, args->N, i);
    const ModelMaterial& m = model.materials[model.triangle_materials[triangle]];
    if (!m.needs_hit_filter()) continue;
    const Vec3 direction{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                         RTCRayN_dir_z(args->ray, args->N, i)};
    if (camera && !m.double_sided && back_face(model, &model.indices[size_t(triangle) * 3], direction)) {
      args->valid[i] = 0;
      continue;
    }
    if (m.alpha_mode == AlphaMode::Opaque) continue;
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const float alpha = coverage_alpha(model, triangle, u, v);
    const Vec3 origin{RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                      RTCRayN_org_z(args->ray, args->N, i)};
    const float xi = m.alpha_mode == AlphaMode::Blend ? hit_uniform(origin, direction, triangle) : 0.0f;
    if (!covers(m, alpha, xi)) args->valid[i] = 0;
  }
}

}  // namespace

void install_hit_filter(RTCGeometry geometry, const Model& model) {
  bool needed = false;
  for (const ModelMaterial& m : model.materials) needed |= m.needs_hit_filter();
  if (!needed) return;
  rtcSetGeometryUserData(geometry, const_cast<Model*>(&model));
  rtcSetGeometryIntersectFilterFunction(geometry, filter);
  rtcSetGeometryOccludedFilterFunction(geometry, filter);
}

float coverage_alpha(const Model& model, uint32_t triangle, float u, float v) {
  const ModelMaterial& m = model.materials[model.triangle_materials[triangle]];
  const uint32_t* tri = &model.indices[size_t(triangle) * 3];
  float alpha = m.base_color_factor.a;
  if (m.base_color) {
    // As the shading reads it (SurfaceHit::uv1): (0, 0) where the model has no second set.
    const bool second = m.base_color->tex_coord == 1;
    const Point2 uv = second ? (model.uvs1.empty() ? Point2{0, 0} : at_barycentric(model.uvs1, tri, u, v))
                             : at_barycentric(model.uvs, tri, u, v);
    alpha *= m.base_color->sample(uv, 0.0f).a;
  }
  if (!model.colors.empty()) {
    const float w = 1.0f - u - v;
    alpha *= model.colors[tri[0]].a * w + model.colors[tri[1]].a * u + model.colors[tri[2]].a * v;
  }
  return alpha;
}

bool covers(const ModelMaterial& m, float alpha, float xi) {
  switch (m.alpha_mode) {
    case AlphaMode::Opaque:
      return true;
    case AlphaMode::Mask:
      return alpha >= m.alpha_cutoff;
    case AlphaMode::Blend:
      return xi < alpha;
  }
  return true;
}

float hit_uniform(Vec3 origin, Vec3 direction, uint32_t primitive) {
  uint64_t h = mix64(primitive);
  for (float f : {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z})
    h = mix64(h ^ std::bit_cast<uint32_t>(f));
  return float(h >> 40) * 0x1p-24f;
}

}  // namespace lp::render
