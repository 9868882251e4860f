#pragma once
// glTF materials as the model's metallic-roughness materials, their textures loaded and checked.
#include <vector>

#include "engine/model/model.hpp"
#include "engine/model/model_textures.hpp"

namespace tinygltf {
class Model;
}

namespace lp::gltf {

// Throws lp::Error(Corrupt) for factors out of range or not finite and for references to textures,
// images, samplers or buffer views that do not exist; Unsupported for texture coordinate sets other
// than 0; texture errors from ModelTextures.
std::vector<ModelMaterial> read_materials(const tinygltf::Model& model, ModelTextures& textures);

// The material of a primitive without one: white, fully metallic and rough, as glTF defines.
ModelMaterial default_material();

}  // namespace lp::gltf
