// The cut a region gets, checked against exhaustive scans computed directly from the pixels.
#include "engine/mediancut/region_splitter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/constants.hpp"
#include "engine/core/rng.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/mediancut/median_cut.hpp"

namespace lp {
namespace {

// A rough map: most pixels dim, a few very bright (like real light probes).
Image rough_map(int width, int height, uint64_t seed) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Rng rng(seed, uint64_t(y) * width + x);
      const double u = rng.uniform_double();
      const float l = float(u < 0.01 ? 1000 * rng.uniform_double() : rng.uniform_double());
      image.set(x, y, {l, 0.5f * l, 0.25f * l});
    }
  return image;
}

struct Direct {
  const Image& image;
  std::vector<double> omega;
  explicit Direct(const Image& img) : image(img), omega(img.height()) {
    for (int y = 0; y < img.height(); ++y) omega[y] = latlong::pixel_solid_angle(y, img.width(), img.height());
  }
  double weight(int x, int y) const { return double(luminance(image.at(x, y), LuminanceMode::Average)) * omega[y]; }
  double energy(const Region& r) const {
    double s = 0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) s += weight(x, y);
    return s;
  }
  // sum w * d^2 about the region's centroid, x in radians at the latitude `theta`, y in radians.
  double variance(const Region& r, double theta) const {
    const double sx = 2 * kPi / image.width() * std::sin(theta), sy = kPi / image.height();
    double w = 0, wx = 0, wy = 0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) w += weight(x, y), wx += weight(x, y) * (x + 0.5), wy += weight(x, y) * (y + 0.5);
    if (w <= 0) return 0;
    const double cx = wx / w, cy = wy / w;
    double v = 0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const double dx = (x + 0.5 - cx) * sx, dy = (y + 0.5 - cy) * sy;
        v += weight(x, y) * (dx * dx + dy * dy);
      }
    return v;
  }
};

Region random_region(int width, int height, uint64_t i) {
  Rng rng(77, i);
  int x0 = int(rng.uniform_double() * width), x1 = int(rng.uniform_double() * width);
  int y0 = int(rng.uniform_double() * height), y1 = int(rng.uniform_double() * height);
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  return {x0, y0, x1 + 2, y1 + 2};  // at least 2 x 2, inside a map 2 larger than the ranges
}

TEST(RegionSplitter, MedianCutIsTheBestBalanceAlongTheLongerSide) {
  const int w = 258, h = 130;
  const Image image = rough_map(w, h, 5);
  const Direct direct(image);
  const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Median);
  const RegionSplitter splitter(*tables.weight, nullptr, SplitRule::Median);
  for (uint64_t i = 0; i < 60; ++i) {
    const Region r = random_region(w - 2, h - 2, i);
    const Cut cut = splitter.choose_cut(r);
    EXPECT_EQ(cut.vertical, splitter.wider_than_tall(r));
    const double total = direct.energy(r);
    auto imbalance = [&](int p) { return std::abs(2 * direct.energy(apply_cut(r, {cut.vertical, p}).first) - total); };
    double best = std::numeric_limits<double>::infinity();
    const int lo = (cut.vertical ? r.x0 : r.y0) + 1, hi = (cut.vertical ? r.x1 : r.y1) - 1;
    for (int p = lo; p <= hi; ++p) best = std::min(best, imbalance(p));
    ASSERT_GE(cut.position, lo);
    ASSERT_LE(cut.position, hi);
    EXPECT_NEAR(imbalance(cut.position), best, 1e-9 * total) << "region " << i;
  }
}

TEST(RegionSplitter, VarianceCutMinimisesTheLargerVariance) {
  const int w = 130, h = 66;
  const Image image = rough_map(w, h, 6);
  const Direct direct(image);
  const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Variance);
  const RegionSplitter splitter(*tables.weight, tables.moments.get(), SplitRule::Variance);
  for (uint64_t i = 0; i < 40; ++i) {
    const Region r = random_region(w - 2, h - 2, i);
    const double theta = kPi * 0.5 * (r.y0 + r.y1) / h;
    auto larger = [&](const Cut& c) {
      const auto [a, b] = apply_cut(r, c);
      return std::max(direct.variance(a, theta), direct.variance(b, theta));
    };
    double best = std::numeric_limits<double>::infinity();
    for (int p = r.x0 + 1; p < r.x1; ++p) best = std::min(best, larger({true, p}));
    for (int p = r.y0 + 1; p < r.y1; ++p) best = std::min(best, larger({false, p}));
    EXPECT_NEAR(larger(splitter.choose_cut(r)), best, 1e-6 * best + 1e-15) << "region " << i;
  }
}

// Viriyothai & Debevec's figure 2: a bright and a dimmer source. Median cut splits the bright one
// (it holds more than half the energy); the variance split puts the cut between them.
TEST(RegionSplitter, VarianceSplitSeparatesTwoSourcesThatMedianCutSplits) {
  const int w = 256, h = 128;
  Image image(w, h);
  for (int y = 60; y < 63; ++y)
    for (int x = 0; x < 3; ++x) {
      image.set(100 + x, y, {100, 100, 100});
      image.set(150 + x, y, {30, 30, 30});
    }
  const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Variance);
  const Region all{0, 0, w, h};
  const Cut median = RegionSplitter(*tables.weight, nullptr, SplitRule::Median).choose_cut(all);
  EXPECT_TRUE(median.vertical);
  EXPECT_GT(median.position, 100);
  EXPECT_LT(median.position, 103);
  const Cut variance = RegionSplitter(*tables.weight, tables.moments.get(), SplitRule::Variance).choose_cut(all);
  EXPECT_TRUE(variance.vertical);
  EXPECT_GE(variance.position, 103);
  EXPECT_LE(variance.position, 150);

  MedianCutParams p;
  p.count = 2;
  p.split = SplitRule::Variance;
  const auto lights = median_cut(image, p, tables).lights;
  ASSERT_EQ(lights.size(), 2u);
  for (const auto& l : lights) {
    EXPECT_EQ(l.pixel_y, 61);
    EXPECT_TRUE(l.pixel_x == 101 || l.pixel_x == 151) << l.pixel_x;
  }
}

TEST(RegionSplitter, RegionsWithoutEnergyAreCutInTheMiddle) {
  const Image image(64, 32);
  const SplitTables tables = build_split_tables(image, LuminanceMode::Average, SplitRule::Variance);
  for (SplitRule rule : {SplitRule::Median, SplitRule::Variance}) {
    const RegionSplitter splitter(*tables.weight, tables.moments.get(), rule);
    const Cut cut = splitter.choose_cut({0, 0, 64, 32});
    EXPECT_TRUE(cut.vertical);
    EXPECT_EQ(cut.position, 32);
    const Cut row = splitter.choose_cut({10, 3, 11, 9});  // one column wide: must cut a row
    EXPECT_FALSE(row.vertical);
    EXPECT_EQ(row.position, 6);
  }
}

}  // namespace
}  // namespace lp
