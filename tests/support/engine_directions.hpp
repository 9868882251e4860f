#pragma once
// What the desktop engines sample at a texel of the files the desktop targets write, written from each
// engine's own source and the frame the target states, for tests to check those files against: the world
// direction (ours: z-up, right-handed) an engine looks along at a texel, and a map whose colour tells
// the world direction.
#include <cmath>
#include <numbers>

#include "engine/core/vec3.hpp"
#include "engine/image/image.hpp"
#include "engine/projection/geometry.hpp"

namespace lp::test {

inline constexpr double kPi = std::numbers::pi;

// 1.5 plus the world direction: every direction its own colour; the sky (+z) bluest.
inline Rgb direction_colour(Vec3d world) {
  return {float(1.5 + world.x), float(1.5 + world.y), float(1.5 + world.z)};
}

// Our lat-long (CONTRIBUTING: theta from +z, phi = 2 pi u from +x towards +y) of direction_colour.
inline Image direction_map(int w, int h) {
  Image map(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double theta = (y + 0.5) / h * kPi, phi = (x + 0.5) / w * 2 * kPi;
      map.set(x, y,
              direction_colour(
                  {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)}));
    }
  return map;
}

// Godot 4's sky shader (servers/rendering/renderer_rd/shaders/environment/sky.glsl): panorama (u, v) =
// (atan(d.x, -d.z) / 2 pi mod 1, acos(d.y) / pi), v from the top row; Godot's frame is world (x, z, -y).
inline Vec3d godot_panorama_texel(double u, double v) {
  const double theta = v * kPi, a = 2 * kPi * u;
  const Vec3d d{std::sin(theta) * std::sin(a), std::cos(theta), -std::sin(theta) * std::cos(a)};
  return {d.x, -d.z, d.y};
}

// Unity's Skybox/Panoramic shader, ToRadialCoords: uv = (0.5 - atan2(d.z, d.x) / 2 pi, 1 - acos(d.y) / pi),
// uv.y from the bottom row; Unity's frame is world (-x, z, -y) (glTF's with x negated, as glTFast imports).
inline Vec3d unity_panorama_texel(double u, double v) {
  const double theta = v * kPi, a = 2 * kPi * (0.5 - u);
  const Vec3d d{std::sin(theta) * std::cos(a), std::cos(theta), std::sin(theta) * std::sin(a)};
  return {-d.x, -d.z, d.y};
}

// Unreal's long-lat cube import (TextureCompressorModule: DirectionToLongLat of the face direction with y
// and z exchanged): u = (1 + atan2(g.x, -g.z) / pi) / 2, v = acos(g.y) / pi for g = (d.x, d.z, d.y), d in
// Unreal's axes; Unreal's frame is world (x, -y, z) (as its FBX import of a right-handed z-up scene).
inline Vec3d unreal_panorama_texel(double u, double v) {
  const double theta = v * kPi, b = kPi * (2 * u - 1);
  const Vec3d g{std::sin(theta) * std::sin(b), std::cos(theta), -std::sin(theta) * std::cos(b)};
  return {g.x, -g.z, g.y};  // d = (g.x, g.z, g.y), world = (d.x, -d.y, d.z)
}

// The GL/Vulkan cube-map table in an engine's own axes: the direction of (a, b) in [-1, 1]^2 on face f
// (+X, -X, +Y, -Y, +Z, -Z), a to the right and b down the face's image.
inline Vec3d gl_cube_direction(int face, double a, double b) {
  switch (face) {
    case 0:
      return {1, -b, -a};
    case 1:
      return {-1, -b, a};
    case 2:
      return {a, 1, b};
    case 3:
      return {a, -1, -b};
    case 4:
      return {a, -b, 1};
    default:
      return {-a, -b, -1};
  }
}
// World directions of Godot's (x, y, z) and Unity's.
inline Vec3d world_from_godot(Vec3d d) {
  return {d.x, -d.z, d.y};
}
inline Vec3d world_from_unity(Vec3d d) {
  return {-d.x, -d.z, d.y};
}

// The number of texels whose colour is off direction_colour(world direction of the texel) by more than
// `tolerance` (sum of the three channels' differences); texel(u, v) gives that direction.
template <class Texel>
int texels_off_direction(const Image& image, Texel texel, float tolerance) {
  int off = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgb want = direction_colour(texel((x + 0.5) / image.width(), (y + 0.5) / image.height()));
      const Rgb got = image.at(x, y);
      if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > tolerance) ++off;
    }
  return off;
}

}  // namespace lp::test
