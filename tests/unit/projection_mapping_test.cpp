// The direction <-> texel mappings of every projection: texel centres map back to their texels, every
// direction lands within a texel of its own, the stated face conventions, seams between cube faces and
// cross cells, the inverses of the square maps, and exact texel solid angles (cube and octahedral sum to
// 4 pi, equal-area texels are all 4 pi / N^2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/core/constants.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"
#include "engine/projection/equal_area.hpp"
#include "engine/projection/octahedral.hpp"
#include "engine/projection/projection_texels.hpp"
#include "engine/projection/spherical_polygon.hpp"
#include "engine/projection/target_panels.hpp"

namespace lp {
namespace {

constexpr Projection kAll[] = {Projection::LatLong, Projection::Cube, Projection::Cross,
                               Projection::Octahedral, Projection::EqualArea};

std::vector<Vec3d> random_directions(int n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Vec3d> out;
  for (int i = 0; i < n; ++i) out.push_back(normalize(Vec3d{normal(rng), normal(rng), normal(rng)}));
  return out;
}

// Splits sides longer than 0.02 degrees: the outline of a texel whose sides are curves.
class FineSides final : public EdgeRule {
 public:
  bool needs_split(Vec3d a, Vec3d b) const override { return angle_between(a, b) > 0.02 * kPi / 180; }
};

TEST(ProjectionMapping, EveryTexelCentreMapsBackToItsTexel) {
  for (const Projection p : kAll)
    for (const int size : {8, 9, 64}) {
      const ImageShape shape = projection_shape(p, size);
      for (int y = 0; y < shape.height; ++y)
        for (int x = 0; x < shape.width; ++x) {
          const Vec3d d = texel_centre_direction(p, shape, x, y);
          if (d == Vec3d{}) continue;  // an empty cell of a cross
          EXPECT_NEAR(length(d), 1.0, 1e-12);
          const Pixel back = texel_containing(p, shape, d);
          ASSERT_EQ(back.x, x) << enum_name(p) << " size " << size << " y " << y;
          ASSERT_EQ(back.y, y) << enum_name(p) << " size " << size << " x " << x;
        }
    }
}

// A direction is no farther from the centre of the texel it falls in than that texel's farthest corner.
TEST(ProjectionMapping, EveryDirectionFallsInATexelAroundIt) {
  for (const Projection p : kAll) {
    const int size = 16;
    const ImageShape shape = projection_shape(p, size);
    SphericalPolygon outline;
    for (const Vec3d d : random_directions(20000)) {
      const Pixel t = texel_containing(p, shape, d);
      ASSERT_TRUE(texel_outline(p, size, t.x, t.y, NoEdgeSplits(), outline)) << enum_name(p);
      const Vec3d centre = texel_centre_direction(p, shape, t.x, t.y);
      double farthest = 0;
      for (const Vec3d corner : outline) farthest = std::max(farthest, angle_between(corner, centre));
      ASSERT_LE(angle_between(d, centre), farthest * 1.0001) << enum_name(p);
    }
  }
}

// The table of engine/projection/cube_face.hpp.
TEST(ProjectionMapping, CubeFacesLookRightAndDownAsStated) {
  struct Row {
    CubeFace face;
    Vec3d look, right, down;
  };
  const Row table[] = {{CubeFace::PosX, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}},
                       {CubeFace::NegX, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                       {CubeFace::PosY, {0, 0, 1}, {1, 0, 0}, {0, -1, 0}},
                       {CubeFace::NegY, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
                       {CubeFace::PosZ, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
                       {CubeFace::NegZ, {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}}};
  for (const Row& r : table) {
    const int f = int(r.face);
    EXPECT_EQ(cube_face_direction(f, {0, 0}), r.look) << enum_name(r.face);
    EXPECT_EQ(cube_face_direction(f, {1, 0}), r.look + r.right) << enum_name(r.face);
    EXPECT_EQ(cube_face_direction(f, {0, 1}), r.look + r.down) << enum_name(r.face);
    const CubeFacePoint p = cube_face_point(r.look * 2 + r.right * 0.5 - r.down * 0.25);
    EXPECT_EQ(p.face, f);
    EXPECT_DOUBLE_EQ(p.ab.x, 0.25);
    EXPECT_DOUBLE_EQ(p.ab.y, -0.125);
    // The OpenGL rule in the cube frame r = (x, z, -y): px has s = -r_z = y, t = -r_y = -z, and so on.
  }
  EXPECT_EQ(enum_names_joined<CubeFace>(), "px, nx, py, ny, pz, nz");
}

// Across every edge of every face, the texel beyond the edge is the neighbouring face's texel there: one
// texel step past the edge lands within two texels' width of the edge texel's centre.
TEST(ProjectionMapping, CubeFaceSeamsJoinNeighbouringTexels) {
  const int size = 16;
  const ImageShape shape = projection_shape(Projection::Cube, size);
  const double step = 2.0 / size;
  for (int face = 0; face < kCubeFaces; ++face)
    for (int k = 0; k < size; ++k) {
      const double along = square_coordinate(k + 0.5, size);
      const Point2d beyond[] = {
          {1 + step / 2, along}, {-1 - step / 2, along}, {along, 1 + step / 2}, {along, -1 - step / 2}};
      for (const Point2d ab : beyond) {
        const Vec3d d = normalize(cube_face_direction(face, ab));
        const Pixel t = texel_containing(Projection::Cube, shape, d);
        ASSERT_NE(t.x / size, face);
        const Vec3d inside =
            normalize(cube_face_direction(face, {std::clamp(ab.x, -1 + step / 2, 1 - step / 2),
                                                 std::clamp(ab.y, -1 + step / 2, 1 - step / 2)}));
        EXPECT_LT(angle_between(texel_centre_direction(Projection::Cube, shape, t.x, t.y), inside), 2 * step);
      }
    }
}

// Pixels side by side in the cross, on faces on both sides, are neighbours on the sphere: the cross
// unfolds the cube with each face kept in its orientation.
TEST(ProjectionMapping, CrossNeighboursAreNeighboursOnTheSphere) {
  const int size = 16;
  const ImageShape shape = projection_shape(Projection::Cross, size);
  int seams = 0;
  for (int y = 0; y < shape.height; ++y)
    for (int x = 0; x < shape.width; ++x) {
      const Vec3d d = texel_centre_direction(Projection::Cross, shape, x, y);
      if (d == Vec3d{}) continue;
      for (const Pixel n : {Pixel{x + 1, y}, Pixel{x, y + 1}}) {
        if (n.x >= shape.width || n.y >= shape.height) continue;
        const Vec3d e = texel_centre_direction(Projection::Cross, shape, n.x, n.y);
        if (e == Vec3d{}) continue;
        EXPECT_LT(angle_between(d, e), 2.0 / size) << x << "," << y;
        seams += (x / size != n.x / size || y / size != n.y / size);
      }
    }
  EXPECT_EQ(seams, 5 * size);  // nx|pz, pz|px, px|nz side by side; py over pz, pz over ny
  const Image strip(6 * size, size);
  EXPECT_EQ(cube_relayout(cube_relayout(strip, Projection::Cube, Projection::Cross), Projection::Cross,
                          Projection::Cube)
                .width(),
            6 * size);
}

TEST(ProjectionMapping, CrossAndStripHoldTheSameFaces) {
  const int size = 4;
  Image strip(6 * size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < 6 * size; ++x) strip.set(x, y, {float(x), float(y), 1});
  const Image cross = cube_relayout(strip, Projection::Cube, Projection::Cross);
  ASSERT_EQ(cross.width(), 4 * size);
  ASSERT_EQ(cross.height(), 3 * size);
  const ImageShape strip_shape = projection_shape(Projection::Cube, size);
  const ImageShape cross_shape = projection_shape(Projection::Cross, size);
  for (int y = 0; y < cross.height(); ++y)
    for (int x = 0; x < cross.width(); ++x) {
      const Vec3d d = texel_centre_direction(Projection::Cross, cross_shape, x, y);
      if (d == Vec3d{}) {
        EXPECT_EQ(cross.at(x, y), (Rgb{0, 0, 0}));
        continue;
      }
      const Pixel s = texel_containing(Projection::Cube, strip_shape, d);
      EXPECT_EQ(cross.at(x, y), strip.at(s.x, s.y));
    }
  const Image back = cube_relayout(cross, Projection::Cross, Projection::Cube);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < 6 * size; ++x) EXPECT_EQ(back.at(x, y), strip.at(x, y));
  const Image face = cube_strip_face(strip, 2);
  EXPECT_EQ(face.at(1, 3), strip.at(2 * size + 1, 3));
}

TEST(ProjectionMapping, EqualAreaMapAndItsInverse) {
  for (const Vec3d d : random_directions(100000)) {
    const Point2d uv = equal_area::square(d);
    ASSERT_LE(std::abs(uv.x), 1.0);
    ASSERT_LE(std::abs(uv.y), 1.0);
    ASSERT_LT(angle_between(equal_area::direction(uv), d), 1e-12);
  }
  for (int i = 1; i < 400; ++i)  // inside the square, off its folded border
    for (int j = 1; j < 400; ++j) {
      const Point2d uv{square_coordinate(i, 400), square_coordinate(j, 400)};
      const Vec3d d = equal_area::direction(uv);
      ASSERT_NEAR(length(d), 1.0, 1e-14);
      const Point2d back = equal_area::square(d);
      ASSERT_NEAR(back.x, uv.x, 1e-12);
      ASSERT_NEAR(back.y, uv.y, 1e-12);
    }
  // The layout of engine/projection/projection.hpp: the centre is the north pole, each corner the south
  // pole, the middle of each side a point of the equator; u has the sign of x and v that of y.
  EXPECT_LT(angle_between(equal_area::direction({0, 0}), {0, 0, 1}), 1e-15);
  for (const Point2d corner : {Point2d{1, 1}, Point2d{-1, 1}, Point2d{1, -1}, Point2d{-1, -1}})
    EXPECT_LT(angle_between(equal_area::direction(corner), {0, 0, -1}), 1e-15);
  EXPECT_LT(angle_between(equal_area::direction({1, 0}), {1, 0, 0}), 1e-15);  // the diamond's corners
  EXPECT_LT(angle_between(equal_area::direction({0, -1}), {0, -1, 0}), 1e-15);
  EXPECT_LT(angle_between(equal_area::direction({0.5, 0.5}), normalize(Vec3d{1, 1, 0})), 1e-15);
}

TEST(ProjectionMapping, OctahedralMapAndItsInverse) {
  for (const Vec3d d : random_directions(100000)) {
    const Point2d uv = octahedral::square(d);
    ASSERT_LT(angle_between(octahedral::direction(uv), d), 1e-12);
  }
  for (int i = 1; i < 400; ++i)
    for (int j = 1; j < 400; ++j) {
      const Point2d uv{square_coordinate(i, 400), square_coordinate(j, 400)};
      const Point2d back = octahedral::square(octahedral::direction(uv));
      ASSERT_NEAR(back.x, uv.x, 1e-12);
      ASSERT_NEAR(back.y, uv.y, 1e-12);
    }
  EXPECT_EQ(octahedral::direction({0, 0}), (Vec3d{0, 0, 1}));
  EXPECT_EQ(octahedral::direction({1, 1}), (Vec3d{0, 0, -1}));
  EXPECT_EQ(octahedral::direction({0, -1}), (Vec3d{0, -1, 0}));
  // The border folds: (1, v) and (1, -v) are one direction.
  EXPECT_EQ(octahedral::direction({1, 0.25}), octahedral::direction({1, -0.25}));
  EXPECT_LT(angle_between(equal_area::direction({1, 0.25}), equal_area::direction({1, -0.25})), 1e-15);
}

// The area of each texel's outline traced finely (its sides are curves of the square map) against
// 4 pi / N^2, the equal-area map's promise.
TEST(ProjectionMapping, EqualAreaTexelsAllCoverFourPiOverNSquared) {
  for (const int size : {2, 5, 16}) {
    const ImageShape shape = projection_shape(Projection::EqualArea, size);
    SphericalPolygon outline;
    double total = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        texel_outline(Projection::EqualArea, size, x, y, FineSides(), outline);
        const double area = std::abs(spherical_polygon_area(outline));
        EXPECT_NEAR(area, 4 * kPi / (size * size), 1e-6 * 4 * kPi / (size * size)) << x << "," << y;
        EXPECT_DOUBLE_EQ(texel_solid_angle(Projection::EqualArea, shape, x, y), 4 * kPi / (size * size));
        total += area;
      }
    EXPECT_NEAR(total, 4 * kPi, 1e-6);
  }
}

TEST(ProjectionMapping, TexelSolidAnglesCoverTheSphere) {
  for (const Projection p : kAll)
    for (const int size : {2, 7, 32}) {
      const ImageShape shape = projection_shape(p, size);
      double total = 0;
      for (int y = 0; y < shape.height; ++y)
        for (int x = 0; x < shape.width; ++x) total += texel_solid_angle(p, shape, x, y);
      EXPECT_NEAR(total, 4 * kPi, 1e-12) << enum_name(p) << " " << size;
    }
}

// The cube's atan formula against the spherical polygon of the texel (its sides are great-circle arcs).
TEST(ProjectionMapping, CubeTexelSolidAngleIsItsSphericalPolygon) {
  const int size = 12;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const Vec3d corners[] = {
          cube_face_direction(0, {square_coordinate(i, size), square_coordinate(j, size)}),
          cube_face_direction(0, {square_coordinate(i, size), square_coordinate(j + 1, size)}),
          cube_face_direction(0, {square_coordinate(i + 1, size), square_coordinate(j + 1, size)}),
          cube_face_direction(0, {square_coordinate(i + 1, size), square_coordinate(j, size)})};
      EXPECT_NEAR(std::abs(spherical_polygon_area(corners)), cube_texel_solid_angle(size, i, j), 1e-15);
    }
}

TEST(ProjectionMapping, ShapesOfEachProjection) {
  EXPECT_EQ(projection_size(Projection::Cross, 400, 300), 100);
  EXPECT_EQ(projection_size(Projection::Cross, 400, 301), std::nullopt);
  EXPECT_EQ(projection_size(Projection::Cross, 402, 300), std::nullopt);
  EXPECT_EQ(projection_size(Projection::Cube, 600, 100), 100);
  EXPECT_EQ(projection_size(Projection::Cube, 600, 101), std::nullopt);
  EXPECT_EQ(projection_size(Projection::EqualArea, 64, 64), 64);
  EXPECT_EQ(projection_size(Projection::Octahedral, 64, 63), std::nullopt);
  EXPECT_EQ(projection_size(Projection::LatLong, 300, 7), 300);
  EXPECT_EQ(equivalent_size(Projection::Cross, 1024), 256);
  EXPECT_EQ(equivalent_size(Projection::EqualArea, 1024), 512);
  EXPECT_EQ(equivalent_latlong_width(Projection::Cube, 256), 1024);
  EXPECT_EQ(equivalent_latlong_width(Projection::Octahedral, 512), 1024);
  EXPECT_EQ(enum_names_joined<Projection>(), "latlong, cube, cross, octahedral, equal-area");
}

}  // namespace
}  // namespace lp
