// The desktop engines' layouts checked against each engine's own mapping from a texel to a direction,
// (tests/support/engine_directions.hpp, from the engines' sources, not from engine_layouts.cpp): a map whose
// colour is a function of the world direction must show, at each engine texel, the colour of the world
// direction the engine samples there (through the frame the target states: Godot (x, z, -y), Unity (-x, z,
// -y), Unreal (x, -y, z)).
#include <gtest/gtest.h>

#include "api/bake/engine_layouts.hpp"
#include "engine/projection/cube_face.hpp"
#include "support/engine_directions.hpp"

namespace lp::api {
namespace {

using namespace lp::test;

void expect_engine_sees_world(const Image& panorama, Vec3d (*texel)(double, double)) {
  EXPECT_EQ(texels_off_direction(panorama, texel, 1e-4f), 0);
}

TEST(BakeEngineLayouts, GodotPanoramaIsTheWorldAsGodotsSkySamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.25});
  expect_engine_sees_world(pano, godot_panorama_texel);
  // Up holds our sky (+z); Godot's forward, -Z at u = 0, is the world's +y.
  EXPECT_NEAR(pano.at(0, 0).z, 2.5f, 0.01f);
  EXPECT_NEAR(pano.at(0, 16).y, 2.5f, 0.01f);
}

TEST(BakeEngineLayouts, UnityPanoramaIsTheWorldAsUnitysPanoramicSkyboxSamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.0});
  expect_engine_sees_world(pano, unity_panorama_texel);
  EXPECT_NEAR(pano.at(16, 16).y, 0.5f, 0.01f);  // Unity's forward +Z, at u = 0.25, is the world's -y
}

TEST(BakeEngineLayouts, UnrealPanoramaIsTheWorldAsUnrealsCubeImportSamplesIt) {
  const Image pano = panorama_columns(direction_map(64, 32), {-1, 0.75});
  expect_engine_sees_world(pano, unreal_panorama_texel);
  EXPECT_NEAR(pano.at(48, 16).x, 2.5f, 0.01f);  // Unreal's forward +X, at u = 0.75, is the world's +x
}

TEST(BakeEngineLayouts, AnOffsetBetweenColumnsInterpolates) {
  Image map(4, 1);
  for (int x = 0; x < 4; ++x) map.set(x, 0, {float(x), 0, 0});
  const Image shifted = panorama_columns(map, {1, 0.125});  // half a column
  EXPECT_FLOAT_EQ(shifted.at(1, 0).x, 0.5f);
  EXPECT_FLOAT_EQ(shifted.at(0, 0).x, 1.5f);  // between column 3 and column 0 across the seam
}

TEST(BakeEngineLayouts, MirroredCubeIsTheWorldAsALeftHandedEngineSamplesIt) {
  const int n = 8;
  Image strip(6 * n, n);  // our strip: cube_face.hpp's faces of the world
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        strip.set(f * n + i, j,
                  direction_colour(
                      normalize(cube_face_direction(f, {(2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1}))));
  const Image unity = cube_strip_x_mirrored(strip);
  int wrong = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3d d = normalize(gl_cube_direction(f, (2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1));
        const Rgb want = direction_colour(world_from_unity(d)), got = unity.at(f * n + i, j);
        if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > 1e-5f) ++wrong;
      }
  EXPECT_EQ(wrong, 0);
  // The same table read in Godot's right-handed frame, world (x, -z, y), fits our strip unchanged.
  wrong = 0;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3d d = normalize(gl_cube_direction(f, (2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1));
        const Rgb want = direction_colour(world_from_godot(d)), got = strip.at(f * n + i, j);
        if (std::abs(got.x - want.x) + std::abs(got.y - want.y) + std::abs(got.z - want.z) > 1e-5f) ++wrong;
      }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace lp::api
