#pragma once
// The scene's geometry in Embree 3: exact spheres (Embree's sphere primitive, hit points re-projected
// onto the analytic sphere), planes (a quad far larger than the rest of the scene), triangle meshes
// from lp::Model (vertex normals, texture coordinates, tangents and materials interpolated at a hit).
// Geometry i of the Embree scene is object i of the SceneDesc.
#include <embree3/rtcore.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/model/model.hpp"
#include "engine/render/camera.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct SurfaceHit {
  float t = 0;
  Vec3 position;
  Vec3 normal;  // unit geometric normal: outward on spheres, the plane's normal, CCW winding on meshes
  uint32_t object = 0;
  Vec3 shading_normal;  // unit interpolated vertex normal (the geometric one on spheres and planes)
  float curvature = 0;  // how fast the shading normal turns along the surface, radians per unit length
  // Mesh objects shaded by the model's materials only (else null and defaults): the model's material of
  // the triangle, the texture coordinates, the tangent (unit, perpendicular to shading_normal) and the
  // gradients of u and v over the triangle (in its plane: a step e along it changes u by dot(du_dp, e);
  // zero on a triangle without uv area).
  const ModelMaterial* material = nullptr;
  Point2 uv;
  Tangent tangent;
  Vec3 du_dp{0, 0, 0}, dv_dp{0, 0, 0};
  // Likewise the second texture coordinate set (TEXCOORD_1) and its gradients, and the vertex colour
  // (COLOR_0): (0, 0), zero and white where the model has none.
  Point2 uv1;
  Vec3 du1_dp{0, 0, 0}, dv1_dp{0, 0, 0};
  Rgba color{1, 1, 1, 1};
};

class EmbreeScene {
 public:
  // Throws lp::Error (InvalidArgument for bad shapes; mesh errors from lp::load_model).
  EmbreeScene(const SceneDesc& scene, const MeshLimits& limits);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // Up to kPacket rays traced together as one coherent packet (rtcIntersect8), for camera rays through
  // neighbouring pixels: Embree then walks the hierarchy once for all of them. They are camera rays:
  // they do not see the back faces of single-sided model materials (hit_filter.hpp). hits[i] is what
  // intersect(rays[i]) gives, up to the rounding of Embree's packet kernels (a ray grazing a silhouette
  // may fall on the other side of it); a ray's result does not depend on the other rays of the packet.
  static constexpr int kPacket = 8;
  void intersect_packet(std::span<const Ray> rays, std::span<std::optional<SurfaceHit>> hits) const;
  // True if anything lies along the ray within (0, t_max).
  bool occluded(const Ray& ray, float t_max = std::numeric_limits<float>::infinity()) const;

  // A ray origin off the surface on the side `direction` leaves to (avoids self-intersection).
  static Vec3 offset_origin(const SurfaceHit& hit, Vec3 direction);

  size_t triangle_count() const { return triangle_count_; }
  RTCScene handle() const { return scene_; }

 private:
  struct Object;
  // What Embree reports of a hit, from a single ray or a packet's lane.
  struct RawHit {
    float t;
    uint32_t object, primitive;
    float u, v;  // barycentric
    Vec3 ng;     // Embree's unnormalised geometric normal
  };
  SurfaceHit surface_hit(const Ray& r, const RawHit& raw) const;
  void fill_mesh_hit(const Object& o, const RawHit& raw, SurfaceHit& hit) const;
  void add_sphere(uint32_t id, const SphereObject& s);
  void add_plane(uint32_t id, const PlaneObject& p, float half_size);
  void add_mesh(uint32_t id, const MeshObject& m, const MeshLimits& limits);
  void attach(RTCGeometry geometry, uint32_t id);

  std::shared_ptr<RTCDeviceTy> device_;
  RTCScene scene_ = nullptr;
  std::vector<Object> objects_;
  size_t triangle_count_ = 0;
};

// Memory a mesh of `triangles` takes while a render holds it: the parsed file, the model and Embree's
// scene and BVH (measured by bench/mesh_memory_bench).
int64_t mesh_memory_bytes(int64_t triangles);

}  // namespace lp::render
