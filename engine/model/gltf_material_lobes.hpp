#pragma once
// The KHR_materials_ior, _specular, _transmission, _volume, _clearcoat and _sheen extensions of a glTF
// material, read into MaterialLobes.
#include <functional>
#include <optional>
#include <string>

#include "engine/model/model.hpp"
#include "engine/texture/texture_decode.hpp"

namespace tinygltf {
struct Material;
struct TextureInfo;
}  // namespace tinygltf

namespace lp::gltf {

// The binding of a texture a material refers to (gltf_materials.cpp), `what` naming it in errors.
using TextureReader = std::function<std::optional<TextureBinding>(const tinygltf::TextureInfo&, ColorSpace,
                                                                  const std::string&)>;

// nullopt when the material uses none of these extensions. Throws lp::Error(Corrupt) for a value of the
// wrong type or out of its range, naming it (`what` names the material).
std::optional<MaterialLobes> read_material_lobes(const tinygltf::Material& material, const std::string& what,
                                                 const TextureReader& texture);

}  // namespace lp::gltf
