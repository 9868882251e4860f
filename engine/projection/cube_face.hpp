#pragma once
// The faces of a cube map: the one place their order and orientation are stated.
//
// Faces follow OpenGL, Vulkan and KTX: the order +X, -X, +Y, -Y, +Z, -Z (px, nx, py, ny, pz, nz) and the
// orientation of the OpenGL specification's cube map table, in a y-up cube frame. Our world is z-up;
// a world direction (x, y, z) is the cube direction (x, z, -y), so the cube's +Y face holds the sky:
//
//   face  looks at (world)  right of the image  down the image
//   px    +x                +y                  -z
//   nx    -x                -y                  -z
//   py    +z (up)           +x                  -y
//   ny    -z (down)         +x                  +y
//   pz    -y                +x                  -z
//   nz    +y                -x                  -z
//
// A face is a square [-1, 1]^2 of coordinates (a, b), a along the rows to the right and b down the
// columns: texel (i, j) of an N x N face covers a in [2i/N - 1, 2(i+1)/N - 1], b likewise with j, row 0
// at the top, and the direction of (a, b) is look + a right + b down. This is the texture coordinate
// (s, t) = ((a + 1)/2, (b + 1)/2) a GL or Vulkan sampler computes for the cube direction, with t = 0 the
// first row of the face's image.
#include <array>

#include "engine/core/enum_table.hpp"
#include "engine/projection/geometry.hpp"

namespace lp {

enum class CubeFace { PosX, NegX, PosY, NegY, PosZ, NegZ };
constexpr auto enum_entries(CubeFace) {
  return std::to_array<EnumEntry<CubeFace>>({{CubeFace::PosX, "px"},
                                             {CubeFace::NegX, "nx"},
                                             {CubeFace::PosY, "py"},
                                             {CubeFace::NegY, "ny"},
                                             {CubeFace::PosZ, "pz"},
                                             {CubeFace::NegZ, "nz"}});
}
inline constexpr int kCubeFaces = 6;

// A face's axes in world coordinates (the table above).
struct CubeFaceFrame {
  Vec3d look, right, down;
};
const CubeFaceFrame& cube_face_frame(int face);

// A point of a face: the face and (a, b) in [-1, 1]^2.
struct CubeFacePoint {
  int face = 0;
  Point2d ab;
};

// The face a direction meets (its largest component; on an edge the first such face in the order) and
// the point on it.
CubeFacePoint cube_face_point(Vec3d direction);
// The direction through (a, b) on a face (not normalised: it lies on the face's plane).
Vec3d cube_face_direction(int face, Point2d ab);
// The exact solid angle of texel (i, j) of an N x N face (the same on every face).
double cube_texel_solid_angle(int size, int i, int j);

}  // namespace lp
