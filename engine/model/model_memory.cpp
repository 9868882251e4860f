#include "engine/model/model_memory.hpp"

#include <tuple>

#include "engine/model/model.hpp"

namespace lp {

int64_t file_load_bytes(int64_t bytes) {
  return 2 * bytes;
}

int64_t geometry_load_bytes(int64_t vertices, int64_t triangles, bool extra_attributes) {
  const auto vertex = int64_t(sizeof(Vec3) * 2 + sizeof(Point2) + sizeof(Tangent) +
                              (extra_attributes ? sizeof(Rgba) + sizeof(Point2) : 0));
  const auto triangle = int64_t(3 * sizeof(uint32_t) + sizeof(uint32_t));  // indices, material
  return 3 * (vertices * vertex + triangles * triangle);
}

int64_t obj_parse_bytes(int64_t triangles, int64_t text_bytes) {
  // Per triangle: three index triples, the face's vertex count, material and smoothing group.
  const int64_t faces = triangles * (3 * 3 * int64_t(sizeof(int)) + 3 * int64_t(sizeof(int)));
  // A map node: the tree's links and colour, the key and the value, and the allocator's header.
  const int64_t node = 4 * int64_t(sizeof(void*)) + int64_t(sizeof(std::tuple<int, int, int>)) +
                       int64_t(sizeof(uint32_t)) + int64_t(sizeof(void*));
  // Numbers take two characters at least ("0 "), and become a float each.
  const int64_t numbers = text_bytes / 2 * int64_t(sizeof(float));
  return faces + 3 * triangles * node + numbers;
}

}  // namespace lp
