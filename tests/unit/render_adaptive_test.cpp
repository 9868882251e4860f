// Adaptive passes of the renderer (Renderer::render_adaptive_pass): exact where every sample is the
// same, unbiased against uniform passes of the same samples, deterministic, counted.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/image/image_io.hpp"
#include "render_test_helpers.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

using test::constant_map;
using test::lighting;
using test::settings;

Image adaptive_render(const SceneDesc& scene, const Lighting& l, const RenderSettings& s,
                      std::shared_ptr<const EnvMap> map, int spp, RenderStats* stats = nullptr) {
  Renderer renderer(scene, l, s, std::move(map));
  std::atomic<bool> cancel{false};
  EXPECT_TRUE(renderer.render_adaptive_pass(spp, cancel, {}));
  if (stats) *stats = renderer.stats();
  return renderer.image();
}

double image_mean(const Image& image) {
  double sum = 0;
  for (const float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

TEST(RenderAdaptive, FurnaceIsExactlyTheAlbedo) {
  // bsdf lighting in the white furnace: every sample of the sphere is 0.5 and of the map 1, so only
  // the silhouette's pixels have a deviation; the sphere is 0.5 exactly whatever its pixels' counts.
  // The samples are 16 per pixel up to the stochastic rounding (spread at most sqrt(1024) / 2 = 16).
  constexpr int kSize = 32;
  RenderStats stats;
  const Image image = adaptive_render(*scene_preset("furnace"), lighting(LightingMode::Bsdf), settings(kSize),
                                      constant_map(1.0f), 16, &stats);
  EXPECT_NEAR(double(stats.samples), 16.0 * kSize * kSize, 64.0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (test::on_preset_sphere(x, y, kSize)) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(image.at(x, y)[k], 0.5f, 1e-5f) << x << "," << y;
      }
}

TEST(RenderAdaptive, FurnaceWithLightSamplesIsTheAlbedoOnAverage) {
  // envmap lighting: MIS of two unbiased estimators, noise only; the same tolerance as the uniform
  // furnace test at 64 spp.
  const Image image = adaptive_render(*scene_preset("furnace"), lighting(LightingMode::EnvMap), settings(32),
                                      constant_map(1.0f), 64);
  EXPECT_NEAR(test::sphere_mean(image), 0.5, 2e-3);
}

TEST(RenderAdaptive, MeanAgreesWithUniformAtEqualSamples) {
  // The materials preset (mirror, glass, metals) under a real map at 16 x 16: over K seeds, the image
  // mean of adaptive passes of 16 spp on average and of uniform passes of 16 spp agree within 4
  // standard errors of their difference, measured from the seeds' spread.
  constexpr int kSeeds = 48, kSpp = 16;
  const SceneDesc scene = *scene_preset("materials");
  const auto map = std::make_shared<const EnvMap>(read_image_file(lp::test::envmap_path("forest.exr")).image);
  Lighting l = lighting(LightingMode::EnvMap);
  l.visible = false;
  double sum[2] = {}, sum_sq[2] = {};
  for (int k = 0; k < kSeeds; ++k) {
    const RenderSettings s = settings(16, 8, 100 + uint64_t(k));
    const double means[2] = {image_mean(test::render(scene, l, s, map, kSpp)),
                             image_mean(adaptive_render(scene, l, s, map, kSpp))};
    for (int m = 0; m < 2; ++m) sum[m] += means[m], sum_sq[m] += means[m] * means[m];
  }
  double mean[2], variance_of_mean[2];
  for (int m = 0; m < 2; ++m) {
    mean[m] = sum[m] / kSeeds;
    variance_of_mean[m] = (sum_sq[m] / kSeeds - mean[m] * mean[m]) / (kSeeds - 1);
  }
  const double standard_error = std::sqrt(variance_of_mean[0] + variance_of_mean[1]);
  RecordProperty("uniform_mean", std::to_string(mean[0]));
  RecordProperty("adaptive_mean", std::to_string(mean[1]));
  RecordProperty("standard_error", std::to_string(standard_error));
  EXPECT_GT(standard_error, 0);
  EXPECT_LT(std::abs(mean[0] - mean[1]), 4 * standard_error)
      << "uniform " << mean[0] << " adaptive " << mean[1] << " standard error " << standard_error;
}

TEST(RenderAdaptive, SameSeedSameImageAtOneAndTwoThreads) {
  const SceneDesc scene = *scene_preset("materials");
  const auto map = std::make_shared<const EnvMap>(read_image_file(lp::test::envmap_path("forest.exr")).image);
  Image images[2];
  RenderStats stats[2];
  for (int t = 0; t < 2; ++t)
    tbb::task_arena(t + 1).execute([&] {
      images[t] = adaptive_render(scene, lighting(LightingMode::EnvMap), settings(24), map, 12, &stats[t]);
    });
  EXPECT_EQ(stats[0].samples, stats[1].samples);
  EXPECT_EQ(stats[0].rays, stats[1].rays);
  ASSERT_EQ(images[0].data().size(), images[1].data().size());
  for (size_t i = 0; i < images[0].data().size(); ++i)
    ASSERT_EQ(images[0].data()[i], images[1].data()[i]) << i;
}

TEST(RenderAdaptive, CountsTheSamplesTracedAndMixesWithUniformPasses) {
  // 24 x 24 pixels: an adaptive pass of 8 spp traces 8 x 576 samples up to the stochastic rounding
  // (spread at most sqrt(576) / 2 = 12; 4 of those), and uniform passes before and after add theirs.
  constexpr int kSize = 24;
  Renderer renderer(*scene_preset("materials"), lighting(LightingMode::EnvMap), settings(kSize),
                    constant_map(1.0f));
  std::atomic<bool> cancel{false};
  ASSERT_TRUE(renderer.render_pass(4, cancel, {}));
  ASSERT_TRUE(renderer.render_adaptive_pass(8, cancel, {}));
  const double adaptive = double(renderer.stats().samples) - 4.0 * kSize * kSize;
  EXPECT_NEAR(adaptive, 8.0 * kSize * kSize, 48.0);
  ASSERT_TRUE(renderer.render_pass(2, cancel, {}));
  EXPECT_NEAR(double(renderer.stats().samples), 14.0 * kSize * kSize, 48.0);
  EXPECT_EQ(renderer.spp_done(), int(renderer.stats().samples / (kSize * kSize)));
}

TEST(RenderAdaptive, IsRefusedAfterResume) {
  Renderer renderer(*scene_preset("sphere"), lighting(LightingMode::EnvMap), settings(8), constant_map(1.0f));
  renderer.resume(Image(8, 8), 4);
  std::atomic<bool> cancel{false};
  EXPECT_THROW(renderer.render_adaptive_pass(4, cancel, {}), Error);
  EXPECT_TRUE(renderer.render_pass(4, cancel, {}));
}

}  // namespace
}  // namespace lp::render
