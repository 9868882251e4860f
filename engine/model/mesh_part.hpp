#pragma once
// A piece of geometry as a loader reads it (a glTF primitive, an OBJ file), completed with what the
// file left out and then appended to the model in world space.
#include <cstdint>
#include <vector>

#include "engine/model/mat4.hpp"
#include "engine/model/model.hpp"

namespace lp {

struct MeshPart {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // empty: flat shading
  std::vector<Point2> uvs;        // empty: none
  std::vector<Tangent> tangents;  // empty: generated
  std::vector<Rgba> colors;       // COLOR_0, empty: none
  std::vector<Point2> uvs1;       // TEXCOORD_1, empty: none
  std::vector<uint32_t> indices;
  std::vector<uint32_t> triangle_materials;  // one per triangle
  size_t triangle_count() const;
};

// Flat normals when there are none (every triangle gets its own three vertices), zero-length normals
// replaced by the area-weighted normal of the vertex's triangles, UVs (0, 0) when there are none,
// tangents generated when there are none (a vertex shared by triangles of opposite UV handedness is
// first split in two). Positions, normals and UVs must be finite.
void complete_part(MeshPart& part);

// The part's vertices through `to_world` (normals by the inverse transpose; a mirroring transform
// reverses the winding and the tangents' handedness), appended to `model`.
void append_part(Model& model, const MeshPart& part, const Mat4& to_world);

}  // namespace lp
