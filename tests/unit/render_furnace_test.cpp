// White furnace tests of the renderer: in a constant environment of radiance 1, a convex diffuse
// object of albedo 0.5 has radiance exactly 0.5 everywhere (it sees nothing but the map), in every
// lighting mode; a glass sphere neither makes nor loses energy, so it has radiance 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "model_test_scenes.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::constant_map;
using test::lighting;
using test::settings;

constexpr int kSize = 32;

struct PixelStats {
  double mean = 0, max_abs_dev = 0;
  int count = 0;
};

PixelStats sphere_stats(const Image& image, double expected) {
  PixelStats s;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      if (!test::on_preset_sphere(x, y, image.width())) continue;
      for (int k = 0; k < 3; ++k) {
        s.mean += image.at(x, y)[k];
        s.max_abs_dev = std::max(s.max_abs_dev, std::abs(double(image.at(x, y)[k]) - expected));
      }
      ++s.count;
    }
  s.mean /= 3.0 * s.count;
  return s;
}

TEST(RenderFurnace, DiffuseSphereIsItsAlbedoInEveryMode) {
  const SceneDesc scene = *scene_preset("furnace");
  struct Expectation {
    LightingMode mode;
    int spp;
    double mean_tol, pixel_tol;
  };
  // bsdf: every cosine-sampled path escapes with weight albedo * 1: exact. envmap / uniform: MIS of
  // two unbiased estimators, noise only. Median cut: the irradiance of 64 point lights from a constant
  // map differs from pi by the discretisation (measured: mean +0.3%, worst pixel 4%).
  const Expectation cases[] = {
      {LightingMode::Bsdf, 16, 1e-5, 1e-5},       {LightingMode::EnvMap, 64, 2e-3, 0.03},
      {LightingMode::Uniform, 64, 2e-3, 0.03},    {LightingMode::MedianCutAll, 16, 0.01, 0.04},
      {LightingMode::MedianCut, 256, 0.01, 0.06},
  };
  for (const auto& c : cases) {
    const Image image = test::render(scene, lighting(c.mode), settings(kSize), constant_map(1.0f), c.spp);
    const PixelStats s = sphere_stats(image, 0.5);
    ASSERT_GT(s.count, 250);
    EXPECT_NEAR(s.mean, 0.5, c.mean_tol) << "mode " << int(c.mode);
    EXPECT_LT(s.max_abs_dev, c.pixel_tol) << "mode " << int(c.mode);
    EXPECT_FLOAT_EQ(image.at(0, 0).x, 1.0f);  // the corners see the map itself
    std::printf("furnace, mode %d, %d spp: mean %.5f, max |pixel - 0.5| %.4f\n", int(c.mode), c.spp, s.mean,
                s.max_abs_dev);
  }
}

TEST(RenderFurnace, GlassSphereConservesEnergy) {
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0].material = DielectricMaterial{1.5f};
  for (LightingMode mode : {LightingMode::EnvMap, LightingMode::Bsdf, LightingMode::MedianCutAll}) {
    const Image image = test::render(scene, lighting(mode), settings(kSize, 64), constant_map(1.0f), 16);
    const PixelStats s = sphere_stats(image, 1.0);
    EXPECT_NEAR(s.mean, 1.0, 1e-3);
    EXPECT_LT(s.max_abs_dev, 5e-3);
    std::printf("glass furnace, mode %d: mean %.6f, max |pixel - 1| %.6f\n", int(mode), s.mean,
                s.max_abs_dev);
  }
}

// The mean over the preset sphere in the furnace of a sphere of `material`, or of a tessellated sphere
// model with a glTF material. Every pixel sees the map through one reflection, and the sphere's pixels
// weight the directions by cos theta: the mean is the cosine-weighted mean of the BSDF's albedo. At
// kWhiteSpp its noise is about 1e-3 (standard deviation over seeds): a mean above 1 + kNoise gains
// energy.
constexpr int kWhiteSpp = 256;
constexpr double kNoise = 3e-3;

double furnace_mean(SceneDesc scene) {
  const Image image =
      test::render(scene, lighting(LightingMode::EnvMap), settings(kSize), constant_map(1.0f), kWhiteSpp);
  return sphere_stats(image, 1.0).mean;
}

double furnace_mean(const Material& material) {
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0].material = material;
  return furnace_mean(scene);
}

double furnace_mean(const ModelMaterial& material) {
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0] = test::model_object(test::sphere_model(48, material));
  return furnace_mean(scene);
}

TEST(RenderFurnace, OtherMaterialsStayAtOrBelowOne) {
  // Mirror of colour 1 reflects everything: exactly 1. So do white plastics, smooth or rough: the base
  // takes what the coat does not reflect (bsdf_plastic.hpp). A conductor of k = 8 absorbs 0.3% at
  // normal incidence, less towards grazing; its roughness costs nothing (microfacet_multiscatter.hpp).
  const ConductorMaterial white_metal{{0.05f, 0.05f, 0.05f}, {8, 8, 8}, 0.3f};
  const std::vector<std::pair<Material, std::pair<double, double>>> cases = {
      {MirrorMaterial{{1, 1, 1}}, {1.0, 1.0}},
      {PlasticMaterial{{1, 1, 1}, 1.5f, 0.0f}, {1.0 - kNoise, 1.0}},
      {PlasticMaterial{{1, 1, 1}, 1.5f, 0.3f}, {1.0 - kNoise, 1.0}},
      {white_metal, {0.995, 1.0}},
  };
  for (const auto& [material, range] : cases) {
    const double mean = furnace_mean(material);
    std::printf("furnace, material %zu: mean %.5f\n", material.index(), mean);
    EXPECT_GE(mean, range.first - kNoise) << material.index();
    EXPECT_LE(mean, range.second + kNoise) << material.index();
  }
}

ModelMaterial white_model(float metallic, float roughness) {
  ModelMaterial m = test::rough_dielectric({1, 1, 1});
  m.metallic_factor = metallic;
  m.roughness_factor = roughness;
  return m;
}

TEST(RenderFurnace, WhiteMetalsReflectEverything) {
  // F = 1: a conductor with k = 20 (F > 0.9999 at every angle) and a glTF metal of base colour 1. The
  // multiple-scattering compensation returns what single scattering loses: without it the means would
  // be E_avg, 0.97 / 0.70 / 0.41 for the conductor (alpha = roughness) and 0.9994 / 0.88 / 0.41 for the
  // glTF metal (alpha = roughness^2). The conductor at 1024 spp, over three seeds: within 6e-4 of 1.
  for (float roughness : {0.1f, 0.5f, 1.0f}) {
    const double conductor =
        furnace_mean(ConductorMaterial{{0.001f, 0.001f, 0.001f}, {20, 20, 20}, roughness});
    const double model = furnace_mean(white_model(1, roughness));
    std::printf("white furnace, roughness %.1f: conductor %.5f, glTF metal %.5f\n", roughness, conductor,
                model);
    EXPECT_NEAR(conductor, 1.0, kNoise) << roughness;
    EXPECT_NEAR(model, 1.0, kNoise) << roughness;
  }
}

TEST(RenderFurnace, FrostedGlassSphereLosesOnlyWhatSingleScatteringMisses) {
  // A rough dielectric neither absorbs nor emits: in the furnace it is at most as bright as the map.
  // Single scattering off its microfacets misses a little light at each crossing (more at grazing
  // angles and inside, where total internal reflection keeps paths bouncing), so the sphere is darker,
  // the more the rougher; a smooth one is exactly 1 (GlassSphereConservesEnergy). Measured 0.958 at
  // alpha 0.1 and 0.583 at 0.5: single-scattering GGX, as Cycles' glass with its GGX distribution.
  SceneDesc scene = *scene_preset("furnace");
  const auto mean_at = [&](float alpha) {
    scene.objects[0].material = DielectricMaterial{1.5f, alpha};
    const Image image = test::render(scene, lighting(LightingMode::EnvMap), settings(kSize, 64),
                                     constant_map(1.0f), kWhiteSpp);
    const double mean = sphere_stats(image, 1.0).mean;
    std::printf("glass furnace, GGX alpha %.1f: %.5f\n", double(alpha), mean);
    return mean;
  };
  const double slightly = mean_at(0.1f), rough = mean_at(0.5f);
  EXPECT_LE(slightly, 1.0 - 0.02);
  EXPECT_GE(slightly, 0.94);
  EXPECT_LE(rough, 0.7);
  EXPECT_GE(rough, 0.55);
}

TEST(RenderFurnace, WhiteModelDielectricReflectsEverything) {
  // A glTF dielectric of base colour 1: its coat reflects E_c, the base the rest (bsdf_plastic.hpp).
  for (float roughness : {0.0f, 0.5f, 1.0f}) {
    const double mean = furnace_mean(white_model(0, roughness));
    std::printf("white furnace, glTF dielectric roughness %.1f: %.5f\n", roughness, mean);
    EXPECT_NEAR(mean, 1.0, kNoise) << roughness;
  }
}

TEST(RenderFurnace, DiffuseCubeMeshAndPlane) {
  // A closed cube mesh is convex too: albedo 0.5 -> 0.5.
  const auto dir = std::filesystem::temp_directory_path() / "lp_render_furnace_cube";
  std::filesystem::create_directories(dir);
  {
    std::ofstream obj(dir / "cube.obj");
    obj << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  }
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0].shape =
      MeshObject{dir / "cube.obj", {0, 0, 0}, 0.5f, {0, 0, 30}, nullptr, false, UpAxis::Y};
  const Image cube =
      test::render(scene, lighting(LightingMode::EnvMap), settings(kSize), constant_map(1.0f), 64);
  EXPECT_NEAR(cube.at(16, 16).x, 0.5f, 0.03f);
  EXPECT_NEAR(cube.at(12, 16).y, 0.5f, 0.03f);
  std::filesystem::remove_all(dir);

  // A plane seen from above sees the upper hemisphere only: albedo 0.5 -> 0.5 as well.
  SceneDesc plane;
  plane.camera = {{0, -2, 3}, {0, 0, 0}, {0, 0, 1}, 40};
  plane.objects = {{PlaneObject{{0, 0, 0}, {0, 0, 1}}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}}};
  const Image floor =
      test::render(plane, lighting(LightingMode::Uniform), settings(kSize), constant_map(1.0f), 64);
  double mean = 0;
  for (int y = 8; y < 24; ++y)
    for (int x = 8; x < 24; ++x) mean += floor.at(x, y).z;
  EXPECT_NEAR(mean / 256, 0.5, 2e-3);
}

TEST(RenderFurnace, InvisibleMapLeavesTheBackgroundBlackButStillLights) {
  Lighting l = lighting(LightingMode::EnvMap);
  l.visible = false;
  l.intensity = 2.0f;
  const Image image = test::render(*scene_preset("furnace"), l, settings(kSize), constant_map(1.0f), 64);
  EXPECT_EQ(image.at(0, 0).x, 0.0f);
  EXPECT_NEAR(sphere_stats(image, 1.0).mean, 1.0, 4e-3);  // intensity 2 x albedo 0.5
}

}  // namespace
}  // namespace lp::render
