#pragma once
// The most memory the parts of a model hold while it loads, from counts known before they are
// allocated: the loaders pass these to ModelLimits::reserve first. They are upper bounds; once loaded,
// a model keeps what Model::memory_bytes counts.
#include <cstdint>
#include <functional>
#include <string>

namespace lp {

// Told, before a loader allocates part of a model (a file's bytes, the geometry, a texture), the most
// bytes that part holds while the model loads, and what it is: a memory budget reserves them here, and
// throws to refuse the model before that part is allocated.
using ModelReserve = std::function<void(int64_t bytes, const std::string& what)>;

// A file of `bytes` read whole, and the one copy its parser makes (tinygltf's buffers, the OBJ text).
int64_t file_load_bytes(int64_t bytes);

// The geometry of `vertices` vertices and `triangles` triangles as a loader builds it: the part it reads,
// a copy of it (flat normals, split tangents), the model's arrays, and one array reallocating as it grows.
// Each vertex has a position, normal, UV and tangent; with `extra_attributes` also a colour and a second
// UV set.
int64_t geometry_load_bytes(int64_t vertices, int64_t triangles, bool extra_attributes);

// tinyobjloader's arrays for an OBJ of `triangles` triangles in `text_bytes` bytes, and the loader's map
// of distinct vertices (at most three per triangle).
int64_t obj_parse_bytes(int64_t triangles, int64_t text_bytes);

}  // namespace lp
