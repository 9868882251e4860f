#pragma once
// Typed reads of glTF accessors, each checked first: the accessor, its buffer view and buffer exist,
// the component type and element type are ones the attribute allows, every element lies inside the
// view and the view inside its buffer, and floats are finite. Failures are lp::Error(Corrupt) naming
// the accessor and what is wrong.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/core/point2.hpp"
#include "engine/core/vec3.hpp"

namespace tinygltf {
class Model;
}

namespace lp::gltf {

// The number of elements of accessor `index` (checked to exist), without reading them.
size_t accessor_count(const tinygltf::Model& model, int index, const std::string& what);

std::vector<Vec3> read_vec3(const tinygltf::Model& model, int index, const std::string& what);
std::vector<std::array<float, 4>> read_vec4(const tinygltf::Model& model, int index, const std::string& what);
// Float, or normalised unsigned byte or short.
std::vector<Point2> read_uv(const tinygltf::Model& model, int index, const std::string& what);
// VEC3 (alpha 1) or VEC4 colours: float, or normalised unsigned byte or short.
std::vector<std::array<float, 4>> read_color(const tinygltf::Model& model, int index,
                                             const std::string& what);
// Unsigned byte, short or int scalars.
std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& what);

// The bytes of buffer view `index`, checked to lie inside its buffer.
std::span<const uint8_t> buffer_view_bytes(const tinygltf::Model& model, int index, const std::string& what);

}  // namespace lp::gltf
