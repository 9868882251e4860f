// Guided CDF inversion gives the cell a binary search over the whole CDF gives, for every u,
// including the floats next to each guide's value and to each CDF entry, and across empty cells.
#include "engine/sampling/cdf_1d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/rng.hpp"

namespace lp {
namespace {

int binary_search_cell(const std::vector<float>& cdf, float u) {
  const int n = int(cdf.size()) - 1;
  return std::clamp(int(std::upper_bound(cdf.begin() + 1, cdf.end(), u) - cdf.begin()) - 1, 0, n - 1);
}

// Weights with runs of zeros, a few huge cells and tiny ones, so that guides span many cells or none.
std::vector<float> awkward_weights(int n, uint64_t seed) {
  Rng rng(seed, 0);
  std::vector<float> w(static_cast<size_t>(n));
  for (float& x : w) {
    const float r = rng.uniform_float();
    x = r < 0.3f ? 0.0f : r < 0.32f ? 1000.0f * r : r < 0.5f ? 1e-6f * r : r;
  }
  std::fill(w.begin(), w.begin() + n / 10, 0.0f);  // a leading run of empty cells
  w.back() = 0;
  return w;
}

std::vector<float> probes(const std::vector<float>& cdf, int g, uint64_t seed) {
  std::vector<float> u{0.0f, 0x1.fffffep-1f};
  for (int j = 0; j <= g; ++j) {
    const float v = float(j) / float(g);
    for (float x : {std::nextafter(v, 0.0f), v, std::nextafter(v, 1.0f)}) u.push_back(x);
  }
  for (float c : cdf)
    for (float x : {std::nextafter(c, 0.0f), c, std::nextafter(c, 1.0f)}) u.push_back(x);
  Rng rng(seed, 1);
  for (int i = 0; i < 20000; ++i) u.push_back(rng.uniform_float());
  std::erase_if(u, [](float x) { return !(x >= 0.0f && x < 1.0f); });
  return u;
}

TEST(Cdf1d, GuidedFindEqualsBinarySearch) {
  for (int n : {1, 2, 3, 7, 64, 1000, 4097}) {
    for (int per_guide : {1, 2, 4, 16}) {
      const std::vector<float> w = awkward_weights(n, uint64_t(n * 31 + per_guide));
      std::vector<float> cdf(size_t(n) + 1);
      cdf_1d::build(w.data(), n, cdf.data());
      const int g = cdf_1d::guide_size(n, per_guide);
      std::vector<uint32_t> guide(size_t(g) + 1);
      cdf_1d::build_guide(cdf.data(), 1, n, g, guide.data());
      for (float u : probes(cdf, g, uint64_t(n))) {
        const int cell = cdf_1d::find(cdf.data(), 1, n, guide.data(), g, u);
        ASSERT_EQ(cell, binary_search_cell(cdf, u)) << "n " << n << ", guide " << g << ", u " << u;
        if (n > 1 && std::any_of(w.begin(), w.end(), [](float x) { return x > 0; })) {
          ASSERT_GT(w[size_t(cell)], 0.0f) << "an empty cell was picked, u " << u;
        }
      }
    }
  }
}

TEST(Cdf1d, InterleavedCdfIsReadThroughItsStride) {
  // CDF entries at every other float, as PiecewiseConstant2D stores them beside the weights.
  const std::vector<float> w{0, 1, 3, 0, 0, 4};
  std::vector<float> table(2 * (w.size() + 1), -1.0f);
  EXPECT_DOUBLE_EQ(cdf_1d::build(w.data(), int(w.size()), table.data(), 2), 8.0);
  const std::vector<float> expected{0, 0, 0.125f, 0.5f, 0.5f, 0.5f, 1};
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(table[2 * i], expected[i]) << i;
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(table[2 * i + 1], -1.0f) << i;  // untouched
  std::vector<uint32_t> guide(3);
  cdf_1d::build_guide(table.data(), 2, int(w.size()), 2, guide.data());
  EXPECT_EQ(cdf_1d::find(table.data(), 2, int(w.size()), guide.data(), 2, 0.0f), 1);
  EXPECT_EQ(cdf_1d::find(table.data(), 2, int(w.size()), guide.data(), 2, 0.2f), 2);
  EXPECT_EQ(cdf_1d::find(table.data(), 2, int(w.size()), guide.data(), 2, 0.5f), 5);
  EXPECT_EQ(cdf_1d::find(table.data(), 2, int(w.size()), guide.data(), 2, 0.99f), 5);
}

}  // namespace
}  // namespace lp
