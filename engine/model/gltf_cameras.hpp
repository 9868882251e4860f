#pragma once
// The cameras a glTF scene places, in the world frame.
#include <vector>

#include "engine/model/gltf_scene.hpp"
#include "engine/model/model.hpp"

namespace tinygltf {
class Model;
}

namespace lp::gltf {

// Throws lp::Error(Corrupt) for a perspective camera whose yfov is not in (0, pi), or a camera whose
// node transform leaves no view direction.
std::vector<ModelCamera> read_cameras(const tinygltf::Model& model, const std::vector<CameraInstance>& nodes);

}  // namespace lp::gltf
