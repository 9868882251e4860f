#include "api/projection_conventions.hpp"

#include <fmt/format.h>

#include "engine/projection/cube_face.hpp"
#include "engine/projection/cube_layout.hpp"

namespace lp::api {
namespace {

// "+x", "-z", ...: a world axis of a face frame.
std::string axis_name(Vec3d v) {
  const double c[3] = {v.x, v.y, v.z};
  for (int i = 0; i < 3; ++i)
    if (c[i] != 0) return fmt::format("{}{}", c[i] > 0 ? '+' : '-', "xyz"[i]);
  return "0";
}

std::string cross_cells() {
  std::string cells;
  for (int face = 0; face < kCubeFaces; ++face) {
    const Pixel cell = cube_layout_pixel(Projection::Cross, 1, {face, 0, 0});
    cells +=
        fmt::format("{}{} at column {}, row {}", face ? "; " : "", enum_name(CubeFace(face)), cell.x, cell.y);
  }
  return cells;
}

constexpr const char* kSquareTexel =
    "texel (x, y) of an N x N square is at u = 2 (x + 0.5) / N - 1, v = 2 (y + 0.5) / N - 1, row 0 at "
    "v = -1";

}  // namespace

std::string projection_convention(Projection projection) {
  switch (projection) {
    case Projection::LatLong:
      return "lat-long: texel (x, y) of a W x H level looks along theta = pi (y + 0.5) / H from +z, phi = 2 "
             "pi "
             "(x + 0.5) / W; row 0 at the top";
    case Projection::Cube:
      return "cube map: six N x N faces (see cube_faces); texel (i, j) of a face looks along look + a right "
             "+ b down, a = 2 (i + 0.5) / N - 1, b = 2 (j + 0.5) / N - 1, row 0 at the top; as one image, "
             "the strip of the six faces side by side in face order (6N x N)";
    case Projection::Cross:
      return "horizontal cross of the cube map's faces (4N x 3N, cells of N x N, see cube_faces): " +
             cross_cells() + "; the other six cells black";
    case Projection::Octahedral:
      return fmt::format(
          "octahedral square (Cigolle et al. 2014): {}; the upper hemisphere (z >= 0) is the diamond |u| + "
          "|v| <= 1, direction (u, v, 1 - |u| - |v|) normalised; the lower one is folded out over the "
          "diagonals, p = d / (|x| + |y| + |z|) at (u, v) = ((1 - |p.y|) sign(p.x), (1 - |p.x|) sign(p.y))",
          kSquareTexel);
    case Projection::EqualArea:
      return fmt::format(
          "Clarberg's equal-area square (pbrt-v4's layout): {}; r = |u| + |v| inside the diamond |u| + |v| "
          "<= 1 (z >= 0), r = 2 - |u| - |v| outside (z < 0); |z| = 1 - r^2, the azimuth in the quadrant "
          "pi / 4 ((|v| - |u|) / r + 1), x and y with the signs of u and v; every texel 4 pi / N^2 sr",
          kSquareTexel);
  }
  return "";
}

std::string cube_faces_convention() {
  std::string text =
      "faces in the KTX, OpenGL and Vulkan order +X, -X, +Y, -Y, +Z, -Z (px, nx, py, ny, pz, nz), oriented "
      "as OpenGL's cube map table in a y-up cube frame: the z-up world direction (x, y, z) is the cube "
      "direction (x, z, -y), so +Y holds the sky. In world axes:";
  for (int face = 0; face < kCubeFaces; ++face) {
    const CubeFaceFrame& f = cube_face_frame(face);
    text += fmt::format("{} {} looks at {}, right {}, down {}", face ? ";" : "", enum_name(CubeFace(face)),
                        axis_name(f.look), axis_name(f.right), axis_name(f.down));
  }
  return text;
}

}  // namespace lp::api
