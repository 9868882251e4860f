#pragma once
// Wavefront OBJ with its MTL materials (see model_loader.hpp for the mapping), textures through `textures`.
#include <string>

#include "engine/model/model.hpp"
#include "engine/model/model_textures.hpp"

namespace lp::obj {

// `mtl`: the text of the material libraries the OBJ names (read by the caller).
Model load(const std::string& obj, const std::string& mtl, const std::string& name, ModelTextures& textures,
           const ModelLimits& limits);

// The material library files an OBJ's `mtllib` lines name, in order.
std::vector<std::string> material_libraries(const std::string& obj);

}  // namespace lp::obj
