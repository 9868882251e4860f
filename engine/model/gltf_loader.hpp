#pragma once
// glTF 2.0 from bytes (.gltf JSON or .glb), its other files through `files`.
#include <cstdint>
#include <span>
#include <string>

#include "engine/model/model.hpp"
#include "engine/model/model_files.hpp"
#include "engine/model/model_textures.hpp"

namespace lp::gltf {

Model load(std::span<const uint8_t> bytes, const std::string& name, ModelFiles& files,
           ModelTextures& textures, const ModelLimits& limits);

}  // namespace lp::gltf
