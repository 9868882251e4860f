#include "api/turntable_schema.hpp"

#include "engine/render/turntable.hpp"

namespace lp::api {
namespace {

nlohmann::json vec3(Vec3 v) {
  return {v.x, v.y, v.z};
}

}  // namespace

nlohmann::json describe_turntable_cameras(std::span<const render::Camera> cameras) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < cameras.size(); ++i) {
    const render::Camera& c = cameras[i];
    out.push_back({{"index", i},
                   {"position", vec3(c.position)},
                   {"look_at", vec3(c.look_at)},
                   {"up", vec3(c.up)},
                   {"fov_deg", c.fov_deg},
                   {"matrix", render::camera_to_world(c)}});
  }
  return out;
}

}  // namespace lp::api
