#include "engine/projection/cube_face.hpp"

#include <cmath>

namespace lp {
namespace {

// The OpenGL table (cube direction r: +X looks along r_x with s = -r_z, t = -r_y, ...), each cube axis
// written in world axes through r = (x, z, -y).
constexpr std::array<CubeFaceFrame, kCubeFaces> kFrames = {{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}},    // px
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},  // nx
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // py
    {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},    // ny
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // pz
    {{0, 1, 0}, {-1, 0, 0}, {0, 0, -1}},   // nz
}};

// The area integral of a face's solid angle from its centre to (a, b).
double corner_solid_angle(double a, double b) {
  return std::atan2(a * b, std::sqrt(a * a + b * b + 1));
}

}  // namespace

const CubeFaceFrame& cube_face_frame(int face) {
  return kFrames[size_t(face)];
}

CubeFacePoint cube_face_point(Vec3d d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  int face;
  if (ax >= ay && ax >= az)
    face = d.x >= 0 ? 0 : 1;
  else if (az >= ay)
    face = d.z >= 0 ? 2 : 3;
  else
    face = d.y <= 0 ? 4 : 5;
  const CubeFaceFrame& f = kFrames[size_t(face)];
  const double look = dot(d, f.look);
  return {face, {dot(d, f.right) / look, dot(d, f.down) / look}};
}

Vec3d cube_face_direction(int face, Point2d ab) {
  const CubeFaceFrame& f = kFrames[size_t(face)];
  return f.look + ab.x * f.right + ab.y * f.down;
}

double cube_texel_solid_angle(int size, int i, int j) {
  const double a0 = 2.0 * i / size - 1, a1 = 2.0 * (i + 1) / size - 1;
  const double b0 = 2.0 * j / size - 1, b1 = 2.0 * (j + 1) / size - 1;
  return corner_solid_angle(a1, b1) - corner_solid_angle(a0, b1) - corner_solid_angle(a1, b0) +
         corner_solid_angle(a0, b0);
}

}  // namespace lp
