#pragma once
// The glTF extensions the loader reads, one line each. A file may require only these
// (extensionsRequired); any other extension it uses is ignored, and its description says where.
#include <algorithm>
#include <iterator>
#include <string_view>

namespace lp::gltf {

inline constexpr std::string_view kSupportedExtensions[] = {
    "KHR_texture_transform",  "KHR_materials_ior",
    "KHR_materials_specular", "KHR_materials_transmission",
    "KHR_materials_volume",   "KHR_materials_clearcoat",
    "KHR_materials_sheen",    "KHR_materials_emissive_strength",
};

inline bool is_supported_extension(std::string_view name) {
  return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) !=
         std::end(kSupportedExtensions);
}

}  // namespace lp::gltf
