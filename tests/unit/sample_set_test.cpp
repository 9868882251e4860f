// Sample sets: reproducible by seed, stratified for any N, low-discrepancy Sobol nets.
#include "engine/envmap/sample_set.hpp"

#include <gtest/gtest.h>

#include <set>

#include "engine/sampling/sobol_2d.hpp"
#include "support/real_maps.hpp"

namespace lp {
namespace {

std::vector<EnvSample> draw(SampleStrategy strategy, uint64_t count, uint64_t seed, uint64_t first = 0,
                            uint64_t n = 0) {
  const auto sampler = test::real_map("forest.exr")->sampler(LuminanceMode::Average);
  std::vector<EnvSample> out(n ? n : count);
  generate_samples(*sampler, {strategy, count, seed}, first, out);
  return out;
}

bool same(const EnvSample& a, const EnvSample& b) {
  return a.pixel_x == b.pixel_x && a.pixel_y == b.pixel_y && a.u == b.u && a.v == b.v && a.pdf == b.pdf;
}

TEST(SampleSet, SameSeedSameSamplesDifferentSeedDifferentSamples) {
  for (auto strategy : {SampleStrategy::Independent, SampleStrategy::Stratified, SampleStrategy::Sobol}) {
    const auto a = draw(strategy, 5000, 42), b = draw(strategy, 5000, 42), c = draw(strategy, 5000, 43);
    int differing = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      ASSERT_TRUE(same(a[i], b[i])) << enum_name(strategy) << " " << i;
      differing += !same(a[i], c[i]);
    }
    EXPECT_GT(differing, 4900) << enum_name(strategy);
  }
}

TEST(SampleSet, ChunksReproduceTheWholeSet) {
  for (auto strategy : {SampleStrategy::Independent, SampleStrategy::Stratified, SampleStrategy::Sobol}) {
    const auto whole = draw(strategy, 1000, 9);
    const auto part = draw(strategy, 1000, 9, 600, 400);
    for (size_t i = 0; i < part.size(); ++i)
      ASSERT_TRUE(same(part[i], whole[600 + i])) << enum_name(strategy);
  }
}

// For any N, the stratified points fall one per cell of an equal-area partition: round(sqrt N)
// bands in u2, band j holding n_j cells of width 1/n_j.
TEST(SampleSet, StratifiedPointsFillEveryStratumOnceForAnyCount) {
  for (uint64_t n : {1ull, 2ull, 7ull, 64ull, 1000ull, 1023ull, 4097ull}) {
    const uint64_t bands = std::max<uint64_t>(1, uint64_t(std::llround(std::sqrt(double(n)))));
    std::set<std::pair<uint64_t, uint64_t>> cells;
    std::vector<uint64_t> band_start(bands + 1, 0);
    for (uint64_t j = 0; j < bands; ++j)
      band_start[j + 1] = band_start[j] + n / bands + (j < n % bands ? 1 : 0);
    ASSERT_EQ(band_start[bands], n);
    for (uint64_t i = 0; i < n; ++i) {
      const Point2 p = stratified_point(n, 5, i);
      const auto cell_index = uint64_t(double(p.y) * double(n));  // which 1/N slice of u2
      const auto band = uint64_t(std::upper_bound(band_start.begin(), band_start.end(), cell_index) -
                                 band_start.begin() - 1);
      const uint64_t in_band = band_start[band + 1] - band_start[band];
      cells.insert({band, uint64_t(double(p.x) * double(in_band))});
    }
    EXPECT_EQ(cells.size(), n) << "N = " << n;
  }
}

// Scrambled Sobol: every 2^k prefix is a (0, k, 2)-net: each elementary interval of area 2^-k,
// of every shape 2^-a x 2^-(k-a), holds exactly one point.
TEST(SampleSet, SobolPrefixesAreZeroNets) {
  const int k = 10;
  const uint64_t n = 1u << k;
  for (uint64_t seed : {0ull, 1ull, 77ull}) {
    std::vector<Point2> pts;
    for (uint64_t i = 0; i < n; ++i) pts.push_back(sobol_point(seed, i));
    for (int a = 0; a <= k; ++a) {
      std::set<std::pair<uint32_t, uint32_t>> cells;
      for (const Point2& p : pts)
        cells.insert({uint32_t(p.x * float(1u << a)), uint32_t(p.y * float(1u << (k - a)))});
      EXPECT_EQ(cells.size(), n) << "seed " << seed << " shape " << a;
    }
  }
}

TEST(SampleSet, StrategiesParseByName) {
  EXPECT_EQ(parse_enum<SampleStrategy>("sobol"), SampleStrategy::Sobol);
  EXPECT_EQ(parse_enum<SampleStrategy>("stratified"), SampleStrategy::Stratified);
  EXPECT_EQ(parse_enum<SampleStrategy>("independent"), SampleStrategy::Independent);
  EXPECT_FALSE(parse_enum<SampleStrategy>("halton"));
}

}  // namespace
}  // namespace lp
