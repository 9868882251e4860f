#include "engine/render/embree_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/frame.hpp"
#include "engine/render/hit_filter.hpp"
#include "engine/render/placed_model.hpp"

namespace lp::render {

struct EmbreeScene::Object {
  enum class Kind { Sphere, Plane, Mesh } kind;
  Vec3 center;  // sphere
  float radius = 0;
  Vec3 normal;  // plane
  Model model;
  std::vector<float> curvatures;  // mesh: SurfaceHit::curvature of each triangle
  bool model_materials = true;
};

namespace {

// One Embree device for the process: devices are thread-safe and costly to create.
std::shared_ptr<RTCDeviceTy> shared_device() {
  static const std::shared_ptr<RTCDeviceTy> device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw Error(ErrorKind::Internal, "cannot create the Embree device");
    return std::shared_ptr<RTCDeviceTy>(d, rtcReleaseDevice);
  }();
  return device;
}

void check_device(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE)
    throw Error(ErrorKind::Internal, std::string("Embree error ") + std::to_string(int(e)) + " " + what);
}

// A distance that dwarfs the rest of the scene, so a finite quad looks like an infinite plane.
float plane_half_size(const SceneDesc& scene) {
  float extent = length(scene.camera.position) + length(scene.camera.look_at);
  for (const auto& o : scene.objects) {
    if (const auto* s = std::get_if<SphereObject>(&o.shape))
      extent = std::max(extent, length(s->center) + s->radius);
    if (const auto* p = std::get_if<PlaneObject>(&o.shape)) extent = std::max(extent, length(p->point));
  }
  return 1e4f * std::max(1.0f, extent);
}

// With n = e1 x e2, the vectors (e2 x n) / |n|^2 and (n x e1) / |n|^2 are the plane's dual basis of
// e1, e2 (each has dot 1 with its own edge and 0 with the other): the gradient of u is their
// combination by u's changes d1, d2 along the edges, and so is v's. Zero for a degenerate triangle.
void uv_gradients(Vec3 e1, Vec3 e2, Vec3 n, Point2 d1, Point2 d2, Vec3& du_dp, Vec3& dv_dp) {
  const float nn = dot(n, n);
  if (!(nn > 0)) return;
  const Vec3 g1 = cross(e2, n) / nn, g2 = cross(n, e1) / nn;
  du_dp = g1 * d1.x + g2 * d2.x;
  dv_dp = g1 * d1.y + g2 * d2.y;
}

// TEXCOORD_1 and COLOR_0 at barycentrics (u, v), where the model has them; the triangle's edges e1, e2
// and normal n give the second set's gradients.
void fill_optional_attributes(const Model& m, const uint32_t* tri, float u, float v, Vec3 e1, Vec3 e2, Vec3 n,
                              SurfaceHit& hit) {
  const float w = 1.0f - u - v;
  if (!m.uvs1.empty()) {
    const Point2 ta = m.uvs1[tri[0]], tb = m.uvs1[tri[1]], tc = m.uvs1[tri[2]];
    hit.uv1 = {ta.x * w + tb.x * u + tc.x * v, ta.y * w + tb.y * u + tc.y * v};
    uv_gradients(e1, e2, n, {tb.x - ta.x, tb.y - ta.y}, {tc.x - ta.x, tc.y - ta.y}, hit.du1_dp, hit.dv1_dp);
  }
  if (!m.colors.empty()) {
    const Rgba &a = m.colors[tri[0]], &b = m.colors[tri[1]], &c = m.colors[tri[2]];
    hit.color = {a.r * w + b.r * u + c.r * v, a.g * w + b.g * u + c.g * v, a.b * w + b.b * u + c.b * v,
                 a.a * w + b.a * u + c.a * v};
  }
}

// The largest turn of a triangle's vertex normals per unit of edge length.
float triangle_curvature(const Model& m, const uint32_t* tri) {
  const Vec3 a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
  const Vec3 na = m.normals[tri[0]], nb = m.normals[tri[1]], nc = m.normals[tri[2]];
  const float ab = length(b - a), bc = length(c - b), ca = length(a - c);
  return std::max({ab > 0 ? length(nb - na) / ab : 0.0f, bc > 0 ? length(nc - nb) / bc : 0.0f,
                   ca > 0 ? length(na - nc) / ca : 0.0f});
}

RTCRay make_ray(const Ray& r, float t_max) {
  RTCRay ray{};
  ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
  ray.dir_x = r.direction.x, ray.dir_y = r.direction.y, ray.dir_z = r.direction.z;
  ray.tnear = 0;
  ray.tfar = t_max;
  ray.mask = ~0u;
  return ray;
}

}  // namespace

EmbreeScene::EmbreeScene(const SceneDesc& scene, const MeshLimits& limits) : device_(shared_device()) {
  scene_ = rtcNewScene(device_.get());
  objects_.resize(scene.objects.size());
  const float half_size = plane_half_size(scene);
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const auto& shape = scene.objects[i].shape;
    if (const auto* s = std::get_if<SphereObject>(&shape))
      add_sphere(i, *s);
    else if (const auto* p = std::get_if<PlaneObject>(&shape))
      add_plane(i, *p, half_size);
    else
      add_mesh(i, std::get<MeshObject>(shape), limits);
  }
  rtcCommitScene(scene_);
  check_device(device_.get(), "building the scene");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
}

void EmbreeScene::attach(RTCGeometry geometry, uint32_t id) {
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene_, geometry, id);
  rtcReleaseGeometry(geometry);
  check_device(device_.get(), "adding a geometry");
}

void EmbreeScene::add_sphere(uint32_t id, const SphereObject& s) {
  s.validate("sphere");
  objects_[id].kind = Object::Kind::Sphere;
  objects_[id].center = s.center;
  objects_[id].radius = s.radius;
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  v[0] = s.center.x, v[1] = s.center.y, v[2] = s.center.z, v[3] = s.radius;
  attach(g, id);
}

void EmbreeScene::add_plane(uint32_t id, const PlaneObject& p, float half_size) {
  p.validate("plane");
  const Frame frame = Frame::from_normal(normalize(p.normal));
  objects_[id].kind = Object::Kind::Plane;
  objects_[id].center = p.point;
  objects_[id].normal = frame.n;
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_QUAD);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
  const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int c = 0; c < 4; ++c) {
    const Vec3 q = p.point + frame.s * (corners[c][0] * half_size) + frame.t * (corners[c][1] * half_size);
    v[3 * c] = q.x, v[3 * c + 1] = q.y, v[3 * c + 2] = q.z;
  }
  auto* idx = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(uint32_t), 1));
  idx[0] = 0, idx[1] = 1, idx[2] = 2, idx[3] = 3;
  attach(g, id);
}

void EmbreeScene::add_mesh(uint32_t id, const MeshObject& m, const MeshLimits& limits) {
  Object& o = objects_[id];
  o.kind = Object::Kind::Mesh;
  o.model = place_model(m, limits);
  o.model_materials = m.model_materials;
  triangle_count_ += o.model.triangle_count();
  o.curvatures.resize(o.model.triangle_count());
  for (size_t t = 0; t < o.curvatures.size(); ++t)
    o.curvatures[t] = triangle_curvature(o.model, &o.model.indices[t * 3]);
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree's own buffers: it reads vertices with 16-byte loads, past the end of a packed array.
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), o.model.positions.size()));
  for (size_t i = 0; i < o.model.positions.size(); ++i) {
    const Vec3& q = o.model.positions[i];
    v[3 * i] = q.x, v[3 * i + 1] = q.y, v[3 * i + 2] = q.z;
  }
  auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(uint32_t), o.model.triangle_count()));
  std::copy(o.model.indices.begin(), o.model.indices.end(), idx);
  if (o.model_materials) install_hit_filter(g, o.model);
  attach(g, id);
}

std::optional<SurfaceHit> EmbreeScene::intersect(const Ray& r) const {
  RayContext context(false);
  RTCRayHit rh{};
  rh.ray = make_ray(r, std::numeric_limits<float>::infinity());
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context.embree, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return surface_hit(r, {rh.ray.tfar,
                         rh.hit.geomID,
                         rh.hit.primID,
                         rh.hit.u,
                         rh.hit.v,
                         {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z}});
}

void EmbreeScene::intersect_packet(std::span<const Ray> rays,
                                   std::span<std::optional<SurfaceHit>> hits) const {
  const int n = int(rays.size());
  if (n == 0) return;
  if (n > kPacket || hits.size() < rays.size())
    throw Error(ErrorKind::InvalidArgument, "intersect_packet: more rays than a packet holds");
  alignas(32) int valid[kPacket];
  alignas(32) RTCRayHit8 rh;
  for (int i = 0; i < kPacket; ++i) {
    const Ray& r = rays[size_t(std::min(i, n - 1))];  // idle lanes repeat a ray, masked off
    valid[i] = i < n ? -1 : 0;
    rh.ray.org_x[i] = r.origin.x, rh.ray.org_y[i] = r.origin.y, rh.ray.org_z[i] = r.origin.z;
    rh.ray.dir_x[i] = r.direction.x, rh.ray.dir_y[i] = r.direction.y, rh.ray.dir_z[i] = r.direction.z;
    rh.ray.tnear[i] = 0;
    rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
    rh.ray.time[i] = 0;
    rh.ray.mask[i] = ~0u;
    rh.ray.id[i] = 0;
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RayContext context(true);
  context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect8(valid, scene_, &context.embree, &rh);
  for (int i = 0; i < n; ++i) {
    if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      hits[size_t(i)].reset();
      continue;
    }
    hits[size_t(i)] = surface_hit(rays[size_t(i)], {rh.ray.tfar[i],
                                                    rh.hit.geomID[i],
                                                    rh.hit.primID[i],
                                                    rh.hit.u[i],
                                                    rh.hit.v[i],
                                                    {rh.hit.Ng_x[i], rh.hit.Ng_y[i], rh.hit.Ng_z[i]}});
  }
}

SurfaceHit EmbreeScene::surface_hit(const Ray& r, const RawHit& raw) const {
  SurfaceHit hit;
  hit.t = raw.t;
  hit.object = raw.object;
  const Object& o = objects_[hit.object];
  const Vec3 p = r.origin + r.direction * hit.t;
  switch (o.kind) {
    case Object::Kind::Sphere:
      hit.normal = normalize(p - o.center);
      hit.position = o.center + hit.normal * o.radius;
      break;
    case Object::Kind::Plane:
      hit.normal = o.normal;
      hit.position = p - o.normal * dot(p - o.center, o.normal);
      break;
    case Object::Kind::Mesh:
      hit.position = p;
      fill_mesh_hit(o, raw, hit);
      return hit;
  }
  hit.shading_normal = hit.normal;
  if (o.kind == Object::Kind::Sphere) hit.curvature = 1.0f / o.radius;
  return hit;
}

void EmbreeScene::fill_mesh_hit(const Object& o, const RawHit& raw, SurfaceHit& hit) const {
  const Model& m = o.model;
  const uint32_t* tri = &m.indices[size_t(raw.primitive) * 3];
  const Vec3 a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
  const Vec3 n = cross(b - a, c - a);
  // Embree skips degenerate triangles, but one of float-rounded area may still be hit: use its normal.
  hit.normal = dot(n, n) > 0 ? normalize(n) : normalize(raw.ng);
  const float w1 = raw.u, w2 = raw.v, w0 = 1.0f - w1 - w2;
  const Vec3 na = m.normals[tri[0]], nb = m.normals[tri[1]], nc = m.normals[tri[2]];
  const Vec3 ns = na * w0 + nb * w1 + nc * w2;
  hit.shading_normal = dot(ns, ns) > 0 ? normalize(ns) : hit.normal;
  hit.curvature = o.curvatures[raw.primitive];
  if (!o.model_materials) return;  // the rest is read by the model's materials only (model_shading.hpp)
  hit.material = &m.materials[m.triangle_materials[raw.primitive]];
  const Point2 ta = m.uvs[tri[0]], tb = m.uvs[tri[1]], tc = m.uvs[tri[2]];
  hit.uv = {ta.x * w0 + tb.x * w1 + tc.x * w2, ta.y * w0 + tb.y * w1 + tc.y * w2};
  uv_gradients(b - a, c - a, n, {tb.x - ta.x, tb.y - ta.y}, {tc.x - ta.x, tc.y - ta.y}, hit.du_dp, hit.dv_dp);
  const Tangent &t0 = m.tangents[tri[0]], &t1 = m.tangents[tri[1]], &t2 = m.tangents[tri[2]];
  const Vec3 t = t0.direction * w0 + t1.direction * w1 + t2.direction * w2;
  const Vec3 t_perp = t - hit.shading_normal * dot(t, hit.shading_normal);  // Gram-Schmidt
  hit.tangent.direction =
      dot(t_perp, t_perp) > 1e-12f ? normalize(t_perp) : Frame::from_normal(hit.shading_normal).s;
  hit.tangent.w = t0.w < 0 ? -1.0f : 1.0f;
  fill_optional_attributes(m, tri, w1, w2, b - a, c - a, n, hit);
}

bool EmbreeScene::occluded(const Ray& r, float t_max) const {
  RayContext context(false);
  RTCRay ray = make_ray(r, t_max);
  rtcOccluded1(scene_, &context.embree, &ray);
  return ray.tfar < 0;
}

Vec3 EmbreeScene::offset_origin(const SurfaceHit& hit, Vec3 direction) {
  const Vec3& p = hit.position;
  const float scale = std::max({1.0f, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float eps = 1e-4f * scale;
  return dot(direction, hit.normal) >= 0 ? p + hit.normal * eps : p - hit.normal * eps;
}

int64_t mesh_memory_bytes(int64_t triangles) {
  // Peak resident bytes per triangle while a mesh is read and its BVH built (the file's text,
  // tinyobjloader's arrays, the model, Embree's BVH): 190 at 980k triangles and 133 at 20k in
  // bench/mesh_memory_bench, rounded up.
  constexpr int64_t kMeshBytesPerTriangle = 256;
  return triangles * kMeshBytesPerTriangle;
}

}  // namespace lp::render
