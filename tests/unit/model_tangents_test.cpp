// Generated tangents: along u, perpendicular to the normal, handedness from the UV layout, and a
// usable frame where texture coordinates are degenerate.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lp
