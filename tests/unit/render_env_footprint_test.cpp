// Environment-map lookups over a footprint: camera rays and rays leaving a mirror see the mean of the
// map over their ray cone (not one aliased texel), while everything MIS weighs reads the importance
// grid, so a render converges to the same image whichever strategy lights it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/core/constants.hpp"
#include "render_test_helpers.hpp"

namespace lp::render {
namespace {

using test::lighting;
using test::settings;

// Stripes `width` texels wide across phi on a 512 x 256 map: radiance 2 and 0 in turn.
std::shared_ptr<const EnvMap> stripes(int width = 1) {
  Image image(512, 256);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) image.set(x, y, (x / width) % 2 ? Rgb{} : Rgb{2, 2, 2});
  return std::make_shared<const EnvMap>(std::move(image));
}

// Grid level 3 for the 512-wide map: footprints may reach texels of 8 x 8.
Lighting coarse_grid(LightingMode mode) {
  Lighting l = lighting(mode);
  l.importance_max_width = 64;
  return l;
}

struct Stats {
  double mean = 0, variance = 0;
};

template <class Keep>
Stats stats(const Image& image, Keep keep) {
  double sum = 0, sq = 0;
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (keep(x, y)) {
        const double v = image.at(x, y).x;
        sum += v, sq += v * v, ++n;
      }
  const double mean = sum / n;
  return {mean, sq / n - mean * mean};
}

Image render_mipmapped(const SceneDesc& scene, const Lighting& l, bool mipmaps, int size, int spp,
                       int stripe_width = 1) {
  RenderSettings s = settings(size);
  s.mipmaps = mipmaps;
  return test::render(scene, l, s, stripes(stripe_width), spp);
}

// A camera at the origin looking along +x at the map alone.
SceneDesc map_only(float fov_deg) {
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0].shape = SphereObject{{0, 0, -50}, 0.1f};  // out of view
  scene.camera.position = {0, 0, 0};
  scene.camera.look_at = {1, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.fov_deg = fov_deg;
  return scene;
}

TEST(RenderEnvFootprint, AWideCameraPixelSeesTheMeanOfTheStripes) {
  // A 90 degree view over 32 pixels: a pixel spans 2.8 degrees, four of the map's 0.7 degree texels.
  const SceneDesc scene = map_only(90);
  const auto all = [](int, int) { return true; };
  const Stats on = stats(render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), true, 32, 1), all);
  const Stats off = stats(render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), false, 32, 1), all);
  std::printf("background at 1 spp: footprint mean %.4f variance %.5f, texel mean %.4f variance %.4f\n",
              on.mean, on.variance, off.mean, off.variance);
  EXPECT_NEAR(on.mean, 1.0, 0.02);
  EXPECT_LT(on.variance, 0.01);
  EXPECT_GT(off.variance, 0.5);  // each pixel sees 0 or 2
}

TEST(RenderEnvFootprint, ManySamplesShareThePixelAndConvergeToItsBoxFilteredImage) {
  // A 22.5 degree view over 16 pixels: a pixel spans two texels, a stripe four. With 256 samples each
  // filters over an eighth of the pixel, and the image converges to the box-filtered stripes (level 0,
  // read bilinearly, against its texels read alone); a footprint of the whole pixel per sample would blur
  // every pixel across its neighbours a second time.
  const SceneDesc scene = map_only(22.5f);
  const Image filtered = render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), true, 16, 256, 4);
  const Image sharp = render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), false, 16, 256, 4);
  double sq = 0, sum = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const double d = filtered.at(x, y).x - sharp.at(x, y).x;
      sq += d * d, sum += sharp.at(x, y).x;
    }
  const double mean = sum / 256, rel_mse = sq / 256 / (mean * mean);
  const Stats contrast = stats(sharp, [](int, int) { return true; });
  std::printf("two-texel pixels at 256 spp: relMSE of the filtered image to level 0 %.5f, contrast %.3f\n",
              rel_mse, contrast.variance);
  EXPECT_GT(contrast.variance, 0.3);  // the stripes are resolved
  // 0.011 here: level 0 read bilinearly against texels read alone; 0.054 with whole-pixel footprints.
  EXPECT_LT(rel_mse, 0.02);
}

TEST(RenderEnvFootprint, ACurvedMirrorReflectsTheMeanOfWhatItsConeCovers) {
  SceneDesc scene = *scene_preset("furnace");
  scene.objects[0].material = MirrorMaterial{{1, 1, 1}};
  const auto on_sphere = [](int x, int y) { return test::on_preset_sphere(x, y, 32); };
  const Stats on = stats(render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), true, 32, 1), on_sphere);
  const Stats off =
      stats(render_mipmapped(scene, coarse_grid(LightingMode::EnvMap), false, 32, 1), on_sphere);
  std::printf("mirror at 1 spp: footprint mean %.4f variance %.5f, texel mean %.4f variance %.4f\n", on.mean,
              on.variance, off.mean, off.variance);
  EXPECT_NEAR(on.mean, 1.0, 0.05);
  EXPECT_LT(on.variance, 0.05 * off.variance);
}

// A sun and a sky, with detail finer than the coarse grid.
std::shared_ptr<const EnvMap> sky() {
  return test::make_map(256, [](Vec3 d) {
    const float sun = dot(d, normalize(Vec3{0.3f, 0.4f, 0.8f})) > 0.995f ? 400.0f : 0.0f;
    const float bands = 0.2f + 0.2f * float(int(std::floor(std::atan2(d.y, d.x) * 40)) % 2 != 0);
    const float sky = d.z > 0 ? 0.5f + 0.5f * d.z : bands;
    return Rgb{sky + sun, sky + 0.8f * sun, sky + 0.6f * sun};
  });
}

TEST(RenderEnvFootprint, MisAndBsdfSamplingAgreeOnACoarseGrid) {
  const SceneDesc scene = *scene_preset("sphere");
  Lighting mis = lighting(LightingMode::EnvMap), bsdf = lighting(LightingMode::Bsdf);
  mis.importance_max_width = bsdf.importance_max_width = 32;  // grid level 3 of the 256-wide map
  const Image a = test::render(scene, mis, settings(24), sky(), 256);
  const Image b = test::render(scene, bsdf, settings(24), sky(), 4096);
  const double ma = test::sphere_mean(a), mb = test::sphere_mean(b);
  std::printf("coarse grid: MIS %.4f, BSDF sampling %.4f\n", ma, mb);
  EXPECT_NEAR(ma, mb, 0.02 * mb);
}

TEST(RenderEnvFootprint, ACoarseGridLightsADiffuseSphereAsTheFullMapDoes) {
  const SceneDesc scene = *scene_preset("sphere");
  Lighting coarse = lighting(LightingMode::EnvMap), full = lighting(LightingMode::EnvMap);
  coarse.importance_max_width = 32;
  const Image a = test::render(scene, coarse, settings(24), sky(), 512);
  const Image b = test::render(scene, full, settings(24), sky(), 512);
  const double ma = test::sphere_mean(a), mb = test::sphere_mean(b);
  std::printf("diffuse sphere: grid 32 wide %.4f, full grid %.4f\n", ma, mb);
  EXPECT_NEAR(ma, mb, 0.02 * mb);
}

}  // namespace
}  // namespace lp::render
