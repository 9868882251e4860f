// The allocation of an adaptive pass's samples (adaptive_allocation.hpp): counts in proportion to the
// neighbours' deviations, and never a function of a pixel's own deviation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/render/adaptive_allocation.hpp"

namespace lp::render {
namespace {

constexpr int kSize = 16;
constexpr uint64_t kBudget = uint64_t{kSize} * kSize * 8;

std::vector<float> random_deviations(uint64_t seed) {
  std::vector<float> sigma(kSize * kSize);
  Rng rng(seed, 0);
  for (float& s : sigma) s = rng.uniform_float() * rng.uniform_float() * 4;
  return sigma;
}

uint64_t total(const std::vector<uint32_t>& counts) {
  return std::accumulate(counts.begin(), counts.end(), uint64_t{0});
}

TEST(AdaptiveAllocation, APixelsOwnDeviationDoesNotChangeItsCount) {
  // A pixel whose own samples were bright (a deviation 1000 times its neighbours') gets exactly the
  // count it gets without them (deviation 0): an interior pixel, an edge pixel and a corner.
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    std::vector<float> sigma = random_deviations(seed);
    for (const int i : {5 * kSize + 7, 3, kSize * kSize - 1}) {
      sigma[size_t(i)] = 0;
      const auto quiet = allocate_samples(sigma, kSize, kSize, kBudget, seed, 0);
      sigma[size_t(i)] = 4000;
      const auto bright = allocate_samples(sigma, kSize, kSize, kBudget, seed, 0);
      EXPECT_EQ(quiet[size_t(i)], bright[size_t(i)]) << "seed " << seed << " pixel " << i;
      // Its neighbours do see it: the pixel to its left (or right) gets more samples.
      const size_t n = size_t(i % kSize == 0 ? i + 1 : i - 1);
      EXPECT_GT(bright[n], quiet[n] + 8) << "seed " << seed << " pixel " << i;
    }
  }
}

TEST(AdaptiveAllocation, OneNoisyPixelSendsTheBudgetToItsNeighbours) {
  // One pixel of deviation 1, all others 0: its 8 neighbours share the adaptive 80% of the budget
  // (the allocation reads neighbours only), every other pixel gets the even 20%. The pixel itself, which
  // sees no deviation but its own, counts as in an image without any: the mean, 8.
  std::vector<float> sigma(kSize * kSize, 0.0f);
  const int centre = 8 * kSize + 8;
  sigma[centre] = 1;
  const auto counts = allocate_samples(sigma, kSize, kSize, kBudget, 7, 0);
  const double even = 0.2 * double(kBudget) / (kSize * kSize);  // 1.6
  const double neighbour = 0.8 * double(kBudget) / 8 + even;    // 204.8 + 1.6
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool near = std::abs(x - 8) <= 1 && std::abs(y - 8) <= 1 && (x != 8 || y != 8);
      const double expected = x == 8 && y == 8 ? 8.0 : near ? neighbour : even;
      const uint32_t c = counts[size_t(y * kSize + x)];
      EXPECT_TRUE(c == uint32_t(std::floor(expected)) || c == uint32_t(std::ceil(expected)))
          << x << "," << y << ": " << c << " for " << expected;
    }
}

TEST(AdaptiveAllocation, CountsSumToTheBudgetAndRespectTheCap) {
  // Stochastic rounding: the total is the budget up to the rounding's spread (at most sqrt(pixels) / 2,
  // so 8 for 256 pixels; 4 of those). No pixel above cap x mean.
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const auto counts =
        allocate_samples(random_deviations(seed), kSize, kSize, kBudget, seed, uint32_t(seed));
    EXPECT_NEAR(double(total(counts)), double(kBudget), 32.0) << "seed " << seed;
    for (const uint32_t c : counts) EXPECT_LE(c, uint32_t(32 * 8));
  }
}

TEST(AdaptiveAllocation, NoDeviationAnywhereGivesEveryPixelTheMean) {
  const std::vector<float> sigma(kSize * kSize, 0.0f);
  const auto counts = allocate_samples(sigma, kSize, kSize, kBudget, 1, 0);
  for (const uint32_t c : counts) EXPECT_EQ(c, 8u);
  EXPECT_THROW(allocate_samples(sigma, kSize, kSize + 1, kBudget, 1, 0), Error);
}

TEST(AdaptiveAllocation, WarmupIsAQuarterAndAtLeastTwo) {
  EXPECT_EQ(adaptive_warmup_spp(1), 1);
  EXPECT_EQ(adaptive_warmup_spp(4), 2);
  EXPECT_EQ(adaptive_warmup_spp(32), 8);
  EXPECT_EQ(adaptive_warmup_spp(512), 128);
}

}  // namespace
}  // namespace lp::render
