#include "engine/model/gltf_cameras.hpp"

#include <fmt/format.h>

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {

std::vector<ModelCamera> read_cameras(const tinygltf::Model& model,
                                      const std::vector<CameraInstance>& nodes) {
  std::vector<ModelCamera> out;
  out.reserve(nodes.size());
  for (const CameraInstance& node : nodes) {
    const tinygltf::Camera& c = model.cameras[size_t(node.camera)];
    ModelCamera camera;
    camera.name = c.name;
    camera.index = uint32_t(node.camera);
    camera.perspective = c.type != "orthographic";
    if (camera.perspective) {
      const double yfov = c.perspective.yfov;
      if (!(yfov > 0 && yfov < kPi))
        throw Error(ErrorKind::Corrupt,
                    fmt::format("camera {} has yfov {}, not in (0, pi)", node.camera, yfov));
      camera.yfov_deg = float(yfov * 180 / kPi);
    }
    // A glTF camera looks down its node's -z with its +y up.
    const Vec3 forward = node.to_world.vector({0, 0, -1}), up = node.to_world.vector({0, 1, 0});
    if (!(length(forward) > 0) || !(length(cross(forward, up)) > 0))
      throw Error(ErrorKind::Corrupt,
                  fmt::format("camera {}'s node transform leaves it no view", node.camera));
    camera.position = node.to_world.point({0, 0, 0});
    camera.forward = normalize(forward);
    camera.up = normalize(up);
    out.push_back(std::move(camera));
  }
  return out;
}

}  // namespace lp::gltf
