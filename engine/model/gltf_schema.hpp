#pragma once
// Checks a glTF document's JSON against the types the glTF 2.0 schema gives the properties we read,
// before tinygltf parses it: tinygltf skips a property of the wrong type and uses its default, so that
// a texture index of -1 or a scale that is a string would load as if absent. Also bounds the nesting
// depth (tinygltf converts `extras` recursively).
#include <cstdint>
#include <span>
#include <string>

namespace lp::gltf {

inline constexpr int kMaxJsonDepth = 64;

// `bytes`: a .gltf file, or a .glb whose JSON chunk is checked. Throws lp::Error(Corrupt) naming the
// property by its path ("materials[0].normalTexture.scale must be a number"), or lp::Error(Unsupported)
// for a glTF 1.0 file.
void check_schema(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace lp::gltf
