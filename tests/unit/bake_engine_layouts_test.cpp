// The desktop engines' layouts checked against each engine's own mapping from a texel to a direction,
// written here from the engines' sources, not from engine_layouts.cpp: a map whose colour is a function of
// the world direction must show, at each engine texel, the colour of the world direction the engine
// samples there (through the frame the target states: Godot (x, z, -y), Unity (-x, z, -y), Unreal
// (x, -y, z)).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "api/bake/engine_layouts.hpp"
#include "engine/projection/cube_face.hpp"

namespace lp::api {
namespace {

constexpr double kPi = std::numbers::pi;

Rgb colour(Vec3d world) {
  return {float(1.5 + world.x), float(1.5 + world.y), float(1.5 + world.z)};
}

// Our lat-long (CONTRIBUTING: theta from +z, phi = 2 pi u from +x towards +y) of `colour`.
Image direction_map(int w, int h) {
  Image map(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double theta = (y + 0.5) / h * kPi, phi = (x + 0.5) / w * 2 * kPi;
      map.set(x, y,
              colour({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)}));
    }
  return map;
}

// The world direction an engine samples at texel centre (u, v) of its panorama (v from the top row).
using EngineTexel = std::function<Vec3d(double u, double v)>;

// Godot 4's sky shader: panorama (u, v) = (atan(d.x, -d.z) / 2 pi mod 1, acos(d.y) / pi); world = (x, -z, y).
Vec3d godot_texel(double u, double v) {
  const double theta = v * kPi, a = 2 * kPi * u;
  const Vec3d d{std::sin(theta) * std::sin(a), std::cos(theta), -std::sin(theta) * std::cos(a)};
  return {d.x, -d.z, d.y};
}

// Unity's Skybox/Panoramic ToRadialCoords: uv = (0.5 - atan2(d.z, d.x) / 2 pi, 1 - acos(d.y) / pi), uv.y
// from the bottom row; world from Unity's (-x, z, -y) = (-d.x, -d.z, d.y).
Vec3d unity_texel(double u, double v) {
  const double theta = v * kPi, a = 2 * kPi * (0.5 - u);
  const Vec3d d{std::sin(theta) * std::cos(a), std::cos(theta), std::sin(theta) * std::sin(a)};
  return {-d.x, -d.z, d.y};
}

// Unreal's long-lat cube import (TextureCompressorModule: DirectionToLongLat of the face direction with y
// and z exchanged): u = (1 + atan2(g.x, -g.z) / pi) / 2, v = acos(g.y) / pi for g = (d.x, d.z, d.y), d in
// Unreal's frame; world from Unreal's (x, -y, z) = (d.x, -d.y, d.z).
Vec3d unreal_texel(double u, double v) {
  const double theta = v * kPi, b = kPi * (2 * u - 1);
  const Vec3d g{std::sin(theta) * std::sin(b), std::cos(theta), -std::sin(theta) * std::cos(b)};
  const Vec3d d{g.x, g.z, g.y};
  return {d.x, -d.y, d.z};
}

void expect_engine_sees_world(const Image& panorama, const EngineTexel& texel) {
  int wrong = 0;
  for (int y = 0; y < panorama.height(); ++y)
    for (int x = 0; x < panorama.width(); ++x) {
      const Rgb want = colour(texel((x + 0.5) / panorama.width(), (y + 0.5) / panorama.height()));
      const Rgb got = panorama.at(x, y);
      if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > 1e-4f) ++wrong;
    }
  EXPECT_EQ(wrong, 0);
}

TEST(BakeEngineLayouts, GodotPanoramaIsTheWorldAsGodotsSkySamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.25});
  expect_engine_sees_world(pano, godot_texel);
  // Up holds our sky (+z); Godot's forward, -Z at u = 0, is the world's +y.
  EXPECT_NEAR(pano.at(0, 0).z, 2.5f, 0.01f);
  EXPECT_NEAR(pano.at(0, 16).y, 2.5f, 0.01f);
}

TEST(BakeEngineLayouts, UnityPanoramaIsTheWorldAsUnitysPanoramicSkyboxSamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.0});
  expect_engine_sees_world(pano, unity_texel);
  EXPECT_NEAR(pano.at(16, 16).y, 0.5f, 0.01f);  // Unity's forward +Z, at u = 0.25, is the world's -y
}

TEST(BakeEngineLayouts, UnrealPanoramaIsTheWorldAsUnrealsCubeImportSamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.75});
  expect_engine_sees_world(pano, unreal_texel);
  EXPECT_NEAR(pano.at(48, 16).x, 2.5f, 0.01f);  // Unreal's forward +X, at u = 0.75, is the world's +x
}

TEST(BakeEngineLayouts, AnOffsetBetweenColumnsInterpolates) {
  Image map(4, 1);
  for (int x = 0; x < 4; ++x) map.set(x, 0, {float(x), 0, 0});
  const Image shifted = panorama_columns(map, {1, 0.125});  // half a column
  EXPECT_FLOAT_EQ(shifted.at(1, 0).x, 0.5f);
  EXPECT_FLOAT_EQ(shifted.at(0, 0).x, 1.5f);  // between column 3 and column 0 across the seam
}

// The GL/Vulkan cube-map table in an engine's own axes: the direction of (a, b) on face f.
Vec3d gl_cube_direction(int face, double a, double b) {
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

TEST(BakeEngineLayouts, MirroredCubeIsTheWorldAsALeftHandedEngineSamplesIt) {
  const int n = 8;
  Image strip(6 * n, n);  // our strip: cube_face.hpp's faces of the world
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        strip.set(f * n + i, j,
                  colour(normalize(cube_face_direction(f, {(2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1}))));
  const Image unity = cube_strip_x_mirrored(strip);
  int wrong = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3d d = normalize(gl_cube_direction(f, (2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1));
        const Rgb want = colour({-d.x, -d.z, d.y}), got = unity.at(f * n + i, j);
        if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > 1e-5f) ++wrong;
      }
  EXPECT_EQ(wrong, 0);
  // The same table read in Godot's right-handed frame, world (x, -z, y), fits our strip unchanged.
  wrong = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3d d = normalize(gl_cube_direction(f, (2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1));
        const Rgb want = colour({d.x, -d.z, d.y}), got = strip.at(f * n + i, j);
        if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > 1e-5f) ++wrong;
      }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace lp::api
