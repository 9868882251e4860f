// glTF's material extensions in the renderer: a thin index-matched window shows the background, an
// absorbing volume attenuates by Beer-Lambert along the path inside, a clearcoat of factor 0 changes
// nothing. The lobes themselves (furnace, reciprocity, chi-square): render_bsdf_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/constants.hpp"
#include "model_test_scenes.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::lighting;
using test::settings;

// Looking straight down -z at the origin from height `height`, up +y.
Camera from_above(float height, float fov_deg) {
  Camera c;
  c.position = {0, 0, height};
  c.look_at = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fov_deg = fov_deg;
  return c;
}

ModelMaterial clear_material(float thickness, Rgb attenuation_color, float attenuation_distance) {
  ModelMaterial m = test::rough_dielectric({1, 1, 1});
  m.roughness_factor = 0;
  MaterialLobes l;
  l.ior = 1;
  l.transmission_factor = 1;
  l.thickness_factor = thickness;
  l.attenuation_color = attenuation_color;
  l.attenuation_distance = attenuation_distance;
  m.lobes = l;
  return m;
}

// The box [-1, 1]^2 x [-depth / 2, depth / 2], closed, normals outward.
Model box_model(float depth, const ModelMaterial& material) {
  Model m;
  const float h = depth / 2;
  const auto face = [&](Vec3 n, Vec3 u, Vec3 v, Vec3 centre) {
    const uint32_t base = uint32_t(m.positions.size());
    for (const auto& [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
      m.positions.push_back(centre + u * a + v * b);
      m.normals.push_back(n);
      m.uvs.push_back({0, 0});
      m.tangents.push_back({normalize(u), 1});
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  };
  // Each face's u x v is its outward normal, so the winding is counter-clockwise seen from outside.
  face({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, h});
  face({0, 0, -1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -h});
  face({1, 0, 0}, {0, 1, 0}, {0, 0, h}, {1, 0, 0});
  face({-1, 0, 0}, {0, 0, h}, {0, 1, 0}, {-1, 0, 0});
  face({0, 1, 0}, {0, 0, h}, {1, 0, 0}, {0, 1, 0});
  face({0, -1, 0}, {1, 0, 0}, {0, 0, h}, {0, -1, 0});
  m.triangle_materials.assign(m.indices.size() / 3, 0);
  m.materials = {material};
  return m;
}

// A map that varies with direction, so a window that bent or blurred the view would show.
std::shared_ptr<const EnvMap> gradient_map() {
  return test::make_map(256, [](Vec3 d) { return Rgb{1.0f + d.x, 1.0f - d.y, 0.5f + 0.4f * d.z}; });
}

TEST(RenderGltfLobes, ThinIndexMatchedWindowShowsTheBackground) {
  SceneDesc window;
  window.camera = from_above(3, 20);
  window.objects = {test::model_object(test::square_model(2, 1, clear_material(0, {1, 1, 1}, INFINITY)))};
  // The same view with the square below the camera's field (turned edge-on and pushed aside).
  SceneDesc open = window;
  std::get<MeshObject>(open.objects[0].shape).translate = {0, 0, 10};
  const auto map = gradient_map();
  const Image through = test::render(window, lighting(LightingMode::EnvMap), settings(16), map, 4);
  const Image seen = test::render(open, lighting(LightingMode::EnvMap), settings(16), map, 4);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(through.at(x, y)[k], seen.at(x, y)[k], 2e-3f * seen.at(x, y)[k]) << x << ", " << y;
}

TEST(RenderGltfLobes, AbsorbingVolumeAttenuatesByBeerLambert) {
  // ior 1: every camera ray goes straight on through the slab, a length depth / cos(theta) of the
  // medium (theta its angle to the axis: up to 5.6 degrees here), whose transmittance is
  // attenuationColor^(length / attenuationDistance) per channel.
  const Rgb color{0.8f, 0.5f, 0.2f};
  const float distance = 0.7f;
  for (float depth : {0.25f, 1.0f}) {
    SceneDesc scene;
    scene.camera = from_above(5, 8);
    scene.objects = {test::model_object(box_model(depth, clear_material(1, color, distance)))};
    const Image image =
        test::render(scene, lighting(LightingMode::EnvMap), settings(8), test::constant_map(1), 4);
    const double half = std::tan(4.0 * kPi / 180);  // of the 8 degree field
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const double px = ((x + 0.5) / 4 - 1) * half, py = ((y + 0.5) / 4 - 1) * half;
        const double length = depth * std::sqrt(1 + px * px + py * py);
        for (int k = 0; k < 3; ++k) {
          const double expected = std::pow(double(color[k]), length / distance);
          ASSERT_NEAR(image.at(x, y)[k], expected, 1e-3 * expected) << depth << " channel " << k;
        }
      }
  }
}

TEST(RenderGltfLobes, ClearcoatOfFactorZeroRendersExactlyLikeNone) {
  const ModelMaterial plain = test::rough_dielectric({0.7f, 0.4f, 0.2f});
  ModelMaterial coated = plain;
  coated.lobes = MaterialLobes{};
  coated.lobes->clearcoat_factor = 0;
  coated.lobes->clearcoat_roughness_factor = 0.3f;
  const auto render = [](const ModelMaterial& m) {
    SceneDesc scene;
    scene.objects = {test::model_object(test::sphere_model(16, m))};
    return test::render(scene, lighting(LightingMode::EnvMap), settings(24), gradient_map(), 4);
  };
  const Image a = render(plain), b = render(coated);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) ASSERT_EQ(a.at(x, y), b.at(x, y)) << x << ", " << y;
}

TEST(RenderGltfLobes, CoatedAndSheenedWhiteSphereInAFurnaceStaysAtMostOne) {
  // A layer takes from the base what it reflects: under a constant map of radiance 1 a white sphere
  // with a clearcoat and a sheen has radiance at most 1. Not 1: the symmetric albedo scaling gives the
  // base less than the layers leave it at grazing angles, and the coat is single scattering (0.89).
  ModelMaterial m = test::rough_dielectric({1, 1, 1});
  m.lobes = MaterialLobes{};
  m.lobes->clearcoat_factor = 1;
  m.lobes->clearcoat_roughness_factor = 0.2f;
  m.lobes->sheen_color_factor = {1, 1, 1};
  m.lobes->sheen_roughness_factor = 0.5f;
  SceneDesc scene;
  scene.objects = {test::model_object(test::sphere_model(32, m))};
  const Image image =
      test::render(scene, lighting(LightingMode::EnvMap), settings(32, 32), test::constant_map(1), 64);
  const double mean = test::sphere_mean(image);
  std::printf("coated and sheened white sphere: %.4f\n", mean);
  EXPECT_LE(mean, 1.0 + 5e-3);
  EXPECT_GT(mean, 0.85);
}

}  // namespace
}  // namespace lp::render
