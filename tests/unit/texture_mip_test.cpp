// Mip pyramids: sizes down to 1 x 1 for any size, and every level keeping the base image's mean.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/rng.hpp"
#include "engine/texture/texture.hpp"

namespace lp {
namespace {

std::vector<float> random_texels(int w, int h, int channels, uint64_t seed) {
  Rng rng(seed, 0);
  std::vector<float> t(size_t(w) * size_t(h) * size_t(channels));
  for (float& v : t) v = rng.uniform_float() * 4.0f;  // HDR-ish values
  return t;
}

std::vector<double> level_mean(const MipLevel& l, int channels) {
  std::vector<double> sum(size_t(channels), 0.0);
  for (size_t i = 0; i < l.texels.size(); ++i) sum[i % size_t(channels)] += l.texels[i];
  for (double& s : sum) s /= double(l.width) * l.height;
  return sum;
}

class MipMean : public testing::TestWithParam<std::pair<int, int>> {};

TEST_P(MipMean, EveryLevelKeepsTheBaseMeanToOnePartPerMillion) {
  const auto [w, h] = GetParam();
  for (int channels : {3, 4}) {
    const Texture t(w, h, channels, random_texels(w, h, channels, uint64_t(w * 1000 + h)));
    const auto base = level_mean(t.level(0), channels);
    for (int l = 1; l < t.level_count(); ++l) {
      const auto mean = level_mean(t.level(l), channels);
      for (int c = 0; c < channels; ++c)
        EXPECT_NEAR(mean[size_t(c)], base[size_t(c)], 1e-6 * base[size_t(c)])
            << w << "x" << h << " level " << l << " channel " << c;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, MipMean,
                         testing::Values(std::pair{1, 1}, std::pair{2, 2}, std::pair{3, 3}, std::pair{5, 3},
                                         std::pair{17, 9}, std::pair{64, 64}, std::pair{1, 7},
                                         std::pair{255, 1}, std::pair{100, 37}, std::pair{513, 257}));

TEST(MipPyramid, LevelsHalveRoundingDownToOneByOne) {
  const Texture t(5, 3, 3, random_texels(5, 3, 3, 1));
  ASSERT_EQ(t.level_count(), 3);
  EXPECT_EQ(t.width(1), 2);
  EXPECT_EQ(t.height(1), 1);
  EXPECT_EQ(t.width(2), 1);
  EXPECT_EQ(t.height(2), 1);
  EXPECT_FLOAT_EQ(t.texel_size(1).x, 0.5f);
  EXPECT_FLOAT_EQ(t.texel_size(0).y, 1.0f / 3.0f);
}

TEST(MipPyramid, OddWidthWeighsTheSharedMiddleTexelHalfToEachSide) {
  // 3 x 1 -> 1 x 1: the single texel averages all three.
  const Texture t(3, 1, 3, {0, 0, 0, 3, 3, 3, 6, 6, 6});
  EXPECT_FLOAT_EQ(t.texel(1, 0, 0).r, 3.0f);
  // 5 x 1 -> 2 x 1: each output covers 2.5 input texels.
  const Texture u(5, 1, 3, {0, 0, 0, 10, 10, 10, 20, 20, 20, 30, 30, 30, 40, 40, 40});
  EXPECT_FLOAT_EQ(u.texel(1, 0, 0).r, (0 + 10 + 0.5f * 20) / 2.5f);
  EXPECT_FLOAT_EQ(u.texel(1, 1, 0).r, (0.5f * 20 + 30 + 40) / 2.5f);
}

TEST(MipPyramid, FootprintChoosesTheLevelWhoseTexelsMatchIt) {
  const Texture t(256, 64, 3, random_texels(256, 64, 3, 2));  // geometric mean size 128
  EXPECT_FLOAT_EQ(t.level_for_footprint(1.0f / 128), 0.0f);
  EXPECT_FLOAT_EQ(t.level_for_footprint(4.0f / 128), 2.0f);
  EXPECT_FLOAT_EQ(t.level_for_footprint(0.1f / 128), 0.0f);  // magnified: level 0
  EXPECT_FLOAT_EQ(t.level_for_footprint(1e6f), float(t.level_count() - 1));
  EXPECT_FLOAT_EQ(t.level_for_footprint(std::nanf("")), 0.0f);
}

}  // namespace
}  // namespace lp
