#pragma once
// What a glTF document holds beyond its triangles: cameras, extensions, the materials' alpha modes and
// extensions, and warnings for what the loader ignores (an extension it does not read, animations,
// skins, morph targets, points and lines), each naming where in the document it is.
#include <vector>

#include "engine/model/gltf_scene.hpp"
#include "engine/model/model.hpp"

namespace tinygltf {
class Model;
}

namespace lp::gltf {

// At most this many warnings are listed; a last one counts the others.
inline constexpr size_t kMaxWarnings = 32;

ModelSource describe_source(const tinygltf::Model& model, const std::vector<MeshInstance>& instances);

}  // namespace lp::gltf
