#include "engine/mediancut/summed_area_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace lp {
namespace {

struct Grid {
  int width, height;
  std::vector<double> values;
  double at(int x, int y) const { return values[size_t(y) * width + x]; }
  // Reference rectangle sum in long double.
  long double sum(int x0, int y0, int x1, int y1) const {
    long double s = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) s += at(x, y);
    return s;
  }
};

Grid random_grid(int width, int height, uint64_t seed, double scale = 1.0) {
  Grid g{width, height, std::vector<double>(size_t(width) * height)};
  for (size_t i = 0; i < g.values.size(); ++i) g.values[i] = scale * Rng(seed, i).uniform_double();
  return g;
}

SummedAreaTable table_of(const Grid& g) {
  return SummedAreaTable(g.width, g.height, [&](int y, double* out) {
    for (int x = 0; x < g.width; ++x) out[x] = g.at(x, y);
  });
}

TEST(SummedAreaTable, BordersAreZeroAndEveryEntryIsAPrefixSum) {
  const Grid g = random_grid(37, 23, 1);
  const SummedAreaTable t = table_of(g);
  for (int x = 0; x <= g.width; ++x) EXPECT_EQ(t.at(x, 0), 0.0);
  for (int y = 0; y <= g.height; ++y) EXPECT_EQ(t.at(0, y), 0.0);
  for (int y = 1; y <= g.height; ++y)
    for (int x = 1; x <= g.width; ++x) EXPECT_NEAR(t.at(x, y), double(g.sum(0, 0, x, y)), 1e-12 * t.total());
  EXPECT_NEAR(t.total(), double(g.sum(0, 0, g.width, g.height)), 1e-12 * t.total());
  EXPECT_EQ(t.width(), 37);
  EXPECT_EQ(t.height(), 23);
}

// Large enough that the row and column passes are split across TBB tasks and column blocks.
TEST(SummedAreaTable, RectangleSumsMatchDirectSums) {
  const Grid g = random_grid(1501, 301, 2);  // 19 strips of 16 rows; a width not a multiple of 4
  const SummedAreaTable t = table_of(g);
  for (uint64_t i = 0; i < 200; ++i) {
    Rng rng(3, i);
    int x0 = int(rng.uniform_double() * g.width), x1 = int(rng.uniform_double() * g.width);
    int y0 = int(rng.uniform_double() * g.height), y1 = int(rng.uniform_double() * g.height);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    const long double expected = g.sum(x0, y0, x1 + 1, y1 + 1);
    EXPECT_NEAR(t.sum(x0, y0, x1 + 1, y1 + 1), double(expected), 1e-9 * double(expected) + 1e-12)
        << x0 << "," << y0 << " - " << x1 << "," << y1;
  }
}

// Double precision: a single small value far down a table with a large total is still recovered
// to many digits (a float table would lose it entirely: 1e-3 against a total of ~1e6).
TEST(SummedAreaTable, SmallRegionsKeepPrecisionUnderALargeTotal) {
  Grid g = random_grid(2048, 1024, 4, 1.0);
  g.values[size_t(1000) * 2048 + 2000] = 1e-3;
  const SummedAreaTable t = table_of(g);
  EXPECT_GT(t.total(), 1e6);
  EXPECT_NEAR(t.sum(2000, 1000, 2001, 1001), 1e-3, 1e-9);
}

TEST(SummedAreaTable, RejectsAnEmptyGrid) {
  EXPECT_THROW(SummedAreaTable(0, 4, [](int, double*) {}), Error);
  EXPECT_THROW(SummedAreaTable(4, 0, [](int, double*) {}), Error);
}

}  // namespace
}  // namespace lp
