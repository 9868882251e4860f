// MIS compensation of the map's light samples (envmap.hpp, SamplerWeights): the same image in the mean
// as the plain distribution, with less noise where the map has a bright source and surfaces are glossy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/fresnel/metals.hpp"
#include "render_test_helpers.hpp"
#include "support/real_maps.hpp"

namespace lp::render {
namespace {

Lighting envmap_lighting(bool compensated) {
  Lighting l = test::lighting(LightingMode::EnvMap);
  l.mis_compensation = compensated;
  return l;
}

// Diffuse and rough gold spheres on a diffuse plane: no mirror or glass, whose caustics would dominate.
SceneDesc diffuse_and_gold() {
  const ConductorPreset& gold = lookup_metal("gold");
  SceneDesc s;
  s.camera = {{0, -5, 1.5f}, {0, 0, -0.2f}, {0, 0, 1}, 35};
  s.objects = {
      {SphereObject{{-0.6f, 0, 0}, 0.5f}, DiffuseMaterial{{0.8f, 0.8f, 0.8f}}},
      {SphereObject{{0.6f, 0, 0}, 0.5f}, ConductorMaterial{gold.eta_rgb(), gold.k_rgb(), 0.3f}},
      {PlaneObject{{0, 0, -0.5f}, {0, 0, 1}}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}},
  };
  return s;
}

double mean_of(const Image& image) {
  double sum = 0;
  for (float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

// Mean squared difference between the images of independent seeds: twice the per-pixel variance.
double seed_variance(const SceneDesc& scene, const Lighting& l, const std::shared_ptr<const EnvMap>& map,
                     int spp) {
  std::vector<Image> images;
  for (uint64_t seed = 1; seed <= 4; ++seed)
    images.push_back(test::render(scene, l, test::settings(32, 8, seed), map, spp));
  double sq = 0;
  int64_t n = 0;
  for (size_t a = 0; a < images.size(); ++a)
    for (size_t b = a + 1; b < images.size(); ++b)
      for (size_t i = 0; i < images[a].data().size(); ++i, ++n) {
        const double d = double(images[a].data()[i]) - images[b].data()[i];
        sq += d * d;
      }
  return sq / double(2 * n);
}

TEST(RenderMisCompensation, TheMeanImageIsThePlainDistributions) {
  // city.exr: a sun of about a fifth of the power, 42 degrees up. Over 1024 spp the two means of the
  // diffuse sphere differ by under 1e-3 relative.
  const auto map = lp::test::real_map("city.exr");
  const SceneDesc scene = *scene_preset("sphere");
  const double plain = mean_of(test::render(scene, envmap_lighting(false), test::settings(32), map, 1024));
  const double compensated =
      mean_of(test::render(scene, envmap_lighting(true), test::settings(32), map, 1024));
  std::printf("sphere on city.exr, 1024 spp: mean %.5f plain, %.5f compensated (%+.5f)\n", plain, compensated,
              compensated / plain - 1);
  EXPECT_NEAR(compensated / plain, 1.0, 2e-3);
}

TEST(RenderMisCompensation, LowersTheNoiseOfDiffuseAndGlossySurfacesUnderASun) {
  const auto map = lp::test::real_map("city.exr");
  const SceneDesc scene = diffuse_and_gold();
  const double plain = seed_variance(scene, envmap_lighting(false), map, 16);
  const double compensated = seed_variance(scene, envmap_lighting(true), map, 16);
  std::printf("diffuse and gold on city.exr, 16 spp: variance %.3g plain, %.3g compensated (ratio %.3f)\n",
              plain, compensated, compensated / plain);
  EXPECT_LT(compensated, 0.85 * plain);
}

}  // namespace
}  // namespace lp::render
