// Generated tangents: along u, perpendicular to the normal, handedness from the UV layout, a usable
// frame where texture coordinates are degenerate, and vertices split where UVs mirror.
#include <gtest/gtest.h>

#include "engine/model/mesh_part.hpp"
#include "engine/model/tangents.hpp"

namespace lp {
namespace {

const std::vector<Vec3> kQuad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<Vec3> kUp(4, Vec3{0, 0, 1});
const std::vector<uint32_t> kIndices{0, 1, 2, 0, 2, 3};

TEST(Tangents, FollowUAndPointTheBitangentUpTheImage) {
  // glTF UVs: v down the image, so the top edge (y = 1) has v = 0.
  const std::vector<Point2> uv{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (const Tangent& t : generate_tangents(kQuad, kUp, uv, kIndices)) {
    EXPECT_NEAR(t.direction.x, 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(t.w, 1.0f);  // cross(+z, +x) = +y, up the image
  }
}

TEST(Tangents, MirroredImageGivesNegativeHandedness) {
  const std::vector<Point2> uv{{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // image upside down on the quad
  for (const Tangent& t : generate_tangents(kQuad, kUp, uv, kIndices)) {
    EXPECT_NEAR(t.direction.x, 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(t.w, -1.0f);
  }
}

TEST(Tangents, RotatedUvsRotateTheTangent) {
  const std::vector<Point2> uv{{1, 1}, {1, 0}, {0, 0}, {0, 1}};  // u grows along -y
  for (const Tangent& t : generate_tangents(kQuad, kUp, uv, kIndices))
    EXPECT_NEAR(t.direction.y, -1.0f, 1e-6f);
}

TEST(Tangents, AreOrthogonalisedAgainstBentNormals) {
  std::vector<Vec3> normals(4, normalize(Vec3{1, 0, 1}));
  const std::vector<Point2> uv{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (const Tangent& t : generate_tangents(kQuad, normals, uv, kIndices)) {
    EXPECT_NEAR(dot(t.direction, normals[0]), 0.0f, 1e-6f);
    EXPECT_NEAR(length(t.direction), 1.0f, 1e-6f);
  }
}

TEST(Tangents, DegenerateUvsGiveAnyPerpendicularUnitTangent) {
  const std::vector<Point2> same(4, Point2{0.5f, 0.5f});
  for (const Tangent& t : generate_tangents(kQuad, kUp, same, kIndices)) {
    EXPECT_NEAR(dot(t.direction, Vec3{0, 0, 1}), 0.0f, 1e-6f);
    EXPECT_NEAR(length(t.direction), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(t.w, 1.0f);
  }
  // Collinear UVs (a zero-area UV triangle) are skipped too.
  const std::vector<Point2> line{{0, 0}, {0.5f, 0}, {1, 0}, {0.25f, 0}};
  for (const Tangent& t : generate_tangents(kQuad, kUp, line, kIndices)) EXPECT_TRUE(finite(t.direction));
  for (Vec3 n : {Vec3{0, 0, -1}, Vec3{1, 0, 0}, normalize(Vec3{-1, 2, -3})})
    EXPECT_NEAR(dot(any_perpendicular(n), n), 0.0f, 1e-6f);
}

// The quad's two triangles share the diagonal 0-2. Triangle (0, 1, 2) has u = x, v = 1 - y; triangle
// (0, 2, 3) has those UVs reflected across the diagonal, u = y, v = 1 - x (so vertex 3 takes vertex 1's
// UVs and the diagonal keeps its own).
const std::vector<Point2> kMirroredUvs{{0, 1}, {1, 1}, {1, 0}, {1, 1}};

TEST(Tangents, VerticesSharedByMirroredTrianglesAreSplit) {
  std::vector<uint32_t> indices = kIndices;
  // UV determinants: +1 for (0, 1, 2), -1 for (0, 2, 3): vertices 0 and 2 keep the first and get a copy
  // (4 and 5) for the second; vertex 3 is only in the second.
  EXPECT_EQ(split_mirrored_vertices(kMirroredUvs, indices), (std::vector<uint32_t>{0, 2}));
  EXPECT_EQ(indices, (std::vector<uint32_t>{0, 1, 2, 4, 5, 3}));
  // Consistent UVs, degenerate ones and an empty mesh split nothing.
  const std::vector<Point2> upright{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (const auto& uvs : {upright, std::vector<Point2>(4, Point2{0.5f, 0.5f})}) {
    indices = kIndices;
    EXPECT_TRUE(split_mirrored_vertices(uvs, indices).empty());
    EXPECT_EQ(indices, kIndices);
  }
  std::vector<uint32_t> none;
  EXPECT_TRUE(split_mirrored_vertices({}, none).empty());
}

TEST(Tangents, EachMirroredTriangleGetsTheTangentOfItsOwnUvGradient) {
  MeshPart part;
  part.positions = kQuad;
  part.normals = kUp;
  part.uvs = kMirroredUvs;
  part.indices = kIndices;
  part.triangle_materials = {0, 0};
  complete_part(part);
  ASSERT_EQ(part.positions.size(), 6u);
  ASSERT_EQ(part.tangents.size(), 6u);
  // (0, 1, 2): u grows along +x, v' = 1 - v along +y = cross(+z, +x): w = +1.
  // (0, 2, 3): u grows along +y, v' = x along +x = -cross(+z, +y): w = -1.
  const std::pair<Vec3, float> expected[] = {{{1, 0, 0}, 1.0f}, {{0, 1, 0}, -1.0f}};
  for (size_t t = 0; t < 2; ++t)
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t v = part.indices[t * 3 + k];
      SCOPED_TRACE(testing::Message() << "triangle " << t << " vertex " << v);
      EXPECT_NEAR(part.tangents[v].direction.x, expected[t].first.x, 1e-6f);
      EXPECT_NEAR(part.tangents[v].direction.y, expected[t].first.y, 1e-6f);
      EXPECT_FLOAT_EQ(part.tangents[v].w, expected[t].second);
      // A copy carries its source's position, normal and UVs.
      EXPECT_EQ(part.positions[v], kQuad[kIndices[t * 3 + k]]);
      EXPECT_EQ(part.normals[v], kUp[0]);
      EXPECT_EQ(part.uvs[v].x, kMirroredUvs[kIndices[t * 3 + k]].x);
      EXPECT_EQ(part.uvs[v].y, kMirroredUvs[kIndices[t * 3 + k]].y);
    }
}

TEST(Tangents, AStripMirroredInUKeepsUnitTangentsAlongTheSharedEdge) {
  // Two unit quads side by side sharing the edge x = 1, the right one's UVs mirrored across it
  // (u = x on the left, u = 2 - x on the right; v = 1 - y on both), as a symmetric model's texture
  // island is reused for its two halves. Averaged, the shared edge's tangents +x and -x would cancel.
  MeshPart part;
  part.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  part.normals.assign(6, Vec3{0, 0, 1});
  part.uvs = {{0, 1}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 0}};
  part.indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  part.triangle_materials.assign(4, 0);
  complete_part(part);
  ASSERT_EQ(part.positions.size(), 8u);  // the shared edge's two vertices, once per side
  for (size_t t = 0; t < 4; ++t)
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t v = part.indices[t * 3 + k];
      const bool right = t >= 2;
      SCOPED_TRACE(testing::Message() << "triangle " << t << " vertex " << v);
      // Left: u grows along +x, up the image is +y = cross(+z, +x): w = +1. Right: u grows along -x,
      // and +y = -cross(+z, -x): w = -1.
      EXPECT_NEAR(part.tangents[v].direction.x, right ? -1.0f : 1.0f, 1e-6f);
      EXPECT_NEAR(part.tangents[v].direction.y, 0.0f, 1e-6f);
      EXPECT_FLOAT_EQ(part.tangents[v].w, right ? -1.0f : 1.0f);
    }
}

}  // namespace
}  // namespace lp
