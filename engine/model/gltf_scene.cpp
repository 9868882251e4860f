#include "engine/model/gltf_scene.hpp"

#include <fmt/format.h>

#include <utility>

#include "engine/core/error.hpp"
#include "engine/model/model_frame.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

[[noreturn]] void corrupt(const std::string& problem) {
  throw Error(ErrorKind::Corrupt, problem);
}

std::array<double, 3> vec3_or(const std::vector<double>& v, std::array<double, 3> fallback, int node,
                              const char* what) {
  if (v.empty()) return fallback;
  if (v.size() != 3) corrupt(fmt::format("node {} {} has {} numbers, not 3", node, what, v.size()));
  return {v[0], v[1], v[2]};
}

Mat4 local_transform(const tinygltf::Node& n, int index) {
  Mat4 m;
  if (!n.matrix.empty()) {
    if (n.matrix.size() != 16)
      corrupt(fmt::format("node {} matrix has {} numbers, not 16", index, n.matrix.size()));
    std::copy(n.matrix.begin(), n.matrix.end(), m.m.begin());
  } else {
    std::array<double, 4> q{0, 0, 0, 1};
    if (!n.rotation.empty()) {
      if (n.rotation.size() != 4)
        corrupt(fmt::format("node {} rotation has {} numbers, not 4", index, n.rotation.size()));
      std::copy(n.rotation.begin(), n.rotation.end(), q.begin());
    }
    m = Mat4::trs(vec3_or(n.translation, {0, 0, 0}, index, "translation"), q,
                  vec3_or(n.scale, {1, 1, 1}, index, "scale"));
  }
  if (!m.finite()) corrupt(fmt::format("node {} has a non-finite transform", index));
  return m;
}

std::vector<int> root_nodes(const tinygltf::Model& model) {
  if (!model.scenes.empty()) {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(scene) >= model.scenes.size())
      corrupt(fmt::format("the default scene {} does not exist ({} scenes)", scene, model.scenes.size()));
    return model.scenes[size_t(scene)].nodes;
  }
  std::vector<bool> child(model.nodes.size());
  for (const auto& n : model.nodes)
    for (int c : n.children)
      if (c >= 0 && size_t(c) < model.nodes.size()) child[size_t(c)] = true;
  std::vector<int> roots;
  for (size_t i = 0; i < model.nodes.size(); ++i)
    if (!child[i]) roots.push_back(int(i));
  return roots;
}

}  // namespace

std::vector<MeshInstance> scene_instances(const tinygltf::Model& model) {
  std::vector<MeshInstance> out;
  std::vector<bool> visited(model.nodes.size());
  // Depth-first with an explicit stack: a deep hierarchy cannot exhaust the call stack, and since
  // every node is visited at most once the walk is linear in the nodes.
  std::vector<std::pair<int, Mat4>> stack;
  for (int root : root_nodes(model)) stack.emplace_back(root, y_up_to_world());
  while (!stack.empty()) {
    auto [index, parent] = std::move(stack.back());
    stack.pop_back();
    if (index < 0 || size_t(index) >= model.nodes.size())
      corrupt(fmt::format("node {} does not exist ({} nodes)", index, model.nodes.size()));
    if (visited[size_t(index)])
      corrupt(fmt::format("node {} is reached twice: the node graph is recursive or a node has two parents",
                          index));
    visited[size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    const Mat4 world = parent * local_transform(node, index);
    if (node.mesh >= 0 || node.mesh < -1) {
      if (size_t(node.mesh) >= model.meshes.size())
        corrupt(fmt::format("node {} refers to mesh {}, which does not exist", index, node.mesh));
      out.push_back({node.mesh, world});
    }
    for (int child : node.children) stack.emplace_back(child, world);
  }
  return out;
}

}  // namespace lp::gltf
