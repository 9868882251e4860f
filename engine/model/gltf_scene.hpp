#pragma once
// The meshes a glTF scene places: each node's mesh with the node's world transform (its local
// transform after its parents', in the world frame of model_frame.hpp). The scene is the default one, else
// the first, else all nodes without a parent.
#include <vector>

#include "engine/model/mat4.hpp"

namespace tinygltf {
class Model;
}

namespace lp::gltf {

struct MeshInstance {
  int mesh = -1;
  Mat4 to_world;
};

// Throws lp::Error(Corrupt) for a node, scene or mesh index out of range, a node reached twice (a
// recursive node graph, or a node with two parents), a malformed or non-finite transform.
std::vector<MeshInstance> scene_instances(const tinygltf::Model& model);

}  // namespace lp::gltf
