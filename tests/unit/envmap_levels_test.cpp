// Coarser levels of a lat-long map: each keeps the map's power (odd sizes too), lookups wrap in u and
// reproduce texels at their centres, and the grid width picks the level.
#include "engine/envmap/envmap_levels.hpp"

#include <gtest/gtest.h>

#include <random>

#include "engine/envmap/envmap.hpp"

namespace lp {
namespace {

EnvMap random_map(int width, int height, uint32_t seed) {
  std::mt19937 rng(seed);
  std::exponential_distribution<float> radiance(1.0f);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, {radiance(rng), radiance(rng), radiance(rng)});
  return EnvMap(std::move(image));
}

TEST(EnvMapLevels, EveryLevelKeepsThePower) {
  for (const auto& [w, h] : {std::pair{64, 32}, std::pair{100, 50}, std::pair{37, 19}, std::pair{6, 3}}) {
    const EnvMap map = random_map(w, h, uint32_t(w));
    const EnvMapLevels levels(map, 10);
    for (int k = 1; k <= levels.coarsest(); ++k) {
      const Rgb power = EnvMap(levels.level(k)).power();
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(power[c], map.power()[c], 2e-6 * map.power()[c]) << w << "x" << h << " level " << k;
    }
    EXPECT_EQ(levels.level(levels.coarsest()).width(), 1);
    EXPECT_EQ(levels.level(levels.coarsest()).height(), 1);
  }
}

TEST(EnvMapLevels, AConstantMapStaysConstant) {
  for (const auto& [w, h] : {std::pair{64, 32}, std::pair{37, 19}}) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) image.set(x, y, {2, 2, 2});
    const EnvMapLevels levels(EnvMap(std::move(image)), 10);
    const float tolerance = 2e-6f;
    for (int k = 1; k <= levels.coarsest(); ++k)
      for (int y = 0; y < levels.level(k).height(); ++y)
        EXPECT_NEAR(levels.level(k).at(0, y).x, 2.0f, tolerance) << w << "x" << h << " level " << k;
  }
}

TEST(EnvMapLevels, MemoryIsWhatTheLevelsHold) {
  const EnvMap map = random_map(100, 50, 3);
  const EnvMapLevels levels(map, 3);
  int64_t bytes = 0;
  for (int k = 1; k <= 3; ++k)
    bytes += EnvMap::image_bytes(levels.level(k).width(), levels.level(k).height());
  EXPECT_EQ(EnvMapLevels::memory_bytes(100, 50, 3), bytes);
  EXPECT_EQ(levels.level(3).width(), 12);
  EXPECT_EQ(levels.level(3).height(), 6);
  // The coarsest level is a map of its own (the renderer's importance grid) holding the level's pixels.
  EXPECT_EQ(&levels.coarsest_map()->image(), &levels.level(3));
  EXPECT_EQ(EnvMapLevels(map, 0).coarsest_map(), nullptr);
}

TEST(EnvMapLevels, TheGridWidthPicksTheFirstLevelThatFits) {
  EXPECT_EQ(EnvMapLevels::level_for_width(8192, 2048), 2);
  EXPECT_EQ(EnvMapLevels::level_for_width(2048, 2048), 0);
  EXPECT_EQ(EnvMapLevels::level_for_width(2049, 2048), 1);
  EXPECT_EQ(EnvMapLevels::level_for_width(1000, 1), 9);  // 1000 halves to 1 in nine steps
}

TEST(EnvMapLevels, BilinearIsTheTexelAtItsCentreAndWrapsInU) {
  const EnvMap map = random_map(16, 8, 7);
  const EnvMapLevels levels(map, 2);
  const Image& image = map.image();
  const Rgb centre = levels.bilinear(0, {(3 + 0.5f) / 16, (5 + 0.5f) / 8});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], image.at(3, 5)[c], 1e-6f);
  // u = 0 lies halfway between the last and the first column.
  const Rgb seam = levels.bilinear(0, {0.0f, (2 + 0.5f) / 8});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(seam[c], 0.5f * (image.at(15, 2)[c] + image.at(0, 2)[c]), 1e-6f);
  // Halfway between two levels is the mean of their lookups.
  const latlong::Uv uv{0.3f, 0.6f};
  const Rgb mid = levels.trilinear(uv, 0.5f), a = levels.bilinear(0, uv), b = levels.bilinear(1, uv);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid[c], 0.5f * (a[c] + b[c]), 1e-6f);
  // Levels beyond the coarsest clamp to it.
  const Rgb far = levels.trilinear(uv, 9.0f), coarsest = levels.bilinear(2, uv);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(far[c], coarsest[c]);
}

TEST(EnvMapLevels, AConeOfOneTexelIsLevelZero) {
  const EnvMap map = random_map(64, 32, 1);
  const EnvMapLevels levels(map, 3);
  EXPECT_NEAR(levels.level_for_angle(kPiF / 32), 0.0f, 1e-6f);
  EXPECT_NEAR(levels.level_for_angle(4 * kPiF / 32), 2.0f, 1e-5f);
}

}  // namespace
}  // namespace lp
