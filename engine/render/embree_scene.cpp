#include "engine/render/embree_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/frame.hpp"

namespace lp::render {

struct EmbreeScene::Object {
  enum class Kind { Sphere, Plane, Mesh } kind;
  Vec3 center;  // sphere
  float radius = 0;
  Vec3 normal;  // plane
  TriangleMesh mesh;
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
  o.mesh = m.model ? placed_model_mesh(*m.model, m) : load_obj_mesh(m, limits);
  triangle_count_ += o.mesh.triangle_count();
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), o.mesh.positions.size()));
  for (size_t i = 0; i < o.mesh.positions.size(); ++i) {
    v[3 * i] = o.mesh.positions[i].x, v[3 * i + 1] = o.mesh.positions[i].y,
          v[3 * i + 2] = o.mesh.positions[i].z;
  }
  auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(uint32_t), o.mesh.triangle_count()));
  std::copy(o.mesh.indices.begin(), o.mesh.indices.end(), idx);
  attach(g, id);
}

std::optional<SurfaceHit> EmbreeScene::intersect(const Ray& r) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = make_ray(r, std::numeric_limits<float>::infinity());
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  SurfaceHit hit;
  hit.t = rh.ray.tfar;
  hit.object = rh.hit.geomID;
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
    case Object::Kind::Mesh: {
      const uint32_t* tri = &o.mesh.indices[size_t(rh.hit.primID) * 3];
      const Vec3 a = o.mesh.positions[tri[0]], b = o.mesh.positions[tri[1]], c = o.mesh.positions[tri[2]];
      const Vec3 n = cross(b - a, c - a);
      // Embree skips degenerate triangles, but one of float-rounded area may still be hit: use its normal.
      hit.normal = dot(n, n) > 0 ? normalize(n) : normalize(Vec3{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
      hit.position = p;
      break;
    }
  }
  return hit;
}

bool EmbreeScene::occluded(const Ray& r, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(r, t_max);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0;
}

Vec3 EmbreeScene::offset_origin(const SurfaceHit& hit, Vec3 direction) {
  const Vec3& p = hit.position;
  const float scale = std::max({1.0f, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float eps = 1e-4f * scale;
  return dot(direction, hit.normal) >= 0 ? p + hit.normal * eps : p - hit.normal * eps;
}

}  // namespace lp::render
