// Median cut on synthetic maps with known answers.
#include "engine/mediancut/median_cut.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/mediancut/subdivision.hpp"

namespace lp {
namespace {

using RadianceFn = std::function<Rgb(int x, int y)>;

EnvMap make_map(int width, int height, const RadianceFn& f) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, f(x, y));
  return EnvMap(std::move(image));
}

// A smooth sky: brighter towards +z and towards phi = 0, tinted.
Rgb smooth_sky(int x, int y, int width, int height) {
  const double theta = kPi * (y + 0.5) / height, phi = 2 * kPi * (x + 0.5) / width;
  const float l = float(1.0 + 0.5 * std::cos(theta) + 0.25 * std::sin(theta) * std::cos(phi));
  return Rgb{1.0f, 0.8f, 0.6f} * l;
}

MedianCutParams params(int count, LightPlacement placement = LightPlacement::Centroid,
                       SplitRule split = SplitRule::Median) {
  MedianCutParams p;
  p.count = count;
  p.placement = placement;
  p.split = split;
  return p;
}

double relative_error(const Power& a, Rgb b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]) / std::abs(double(b[c])));
  return worst;
}

// Every pixel belongs to exactly one light's region.
void expect_partition(const MedianCutResult& r, int width, int height) {
  std::vector<int> cover(size_t(width) * height, 0);
  for (const auto& light : r.lights) {
    ASSERT_GE(light.region.x0, 0);
    ASSERT_GE(light.region.y0, 0);
    ASSERT_LE(light.region.x1, width);
    ASSERT_LE(light.region.y1, height);
    ASSERT_GT(light.region.pixel_count(), 0);
    for (int y = light.region.y0; y < light.region.y1; ++y)
      for (int x = light.region.x0; x < light.region.x1; ++x) ++cover[size_t(y) * width + x];
  }
  EXPECT_TRUE(std::all_of(cover.begin(), cover.end(), [](int c) { return c == 1; }));
}

TEST(MedianCut, RegionsPartitionTheMapForAnyCount) {
  const EnvMap map = make_map(128, 64, [](int x, int y) { return smooth_sky(x, y, 128, 64); });
  for (SplitRule split : {SplitRule::Median, SplitRule::Variance})
    for (int count : {1, 2, 3, 7, 64, 100, 256, 1000}) {
      SCOPED_TRACE(testing::Message() << "count " << count << " split " << enum_name(split));
      const auto r = median_cut(map, params(count, LightPlacement::Centroid, split));
      EXPECT_EQ(r.lights.size(), size_t(count));
      expect_partition(r, 128, 64);
    }
}

TEST(MedianCut, EveryPixelCanBecomeALight) {
  const EnvMap map = make_map(16, 8, [](int x, int y) { return smooth_sky(x, y, 16, 8); });
  const auto r = median_cut(map, params(128));
  EXPECT_EQ(r.lights.size(), 128u);
  expect_partition(r, 16, 8);
  for (const auto& light : r.lights) EXPECT_EQ(light.region.pixel_count(), 1);
}

TEST(MedianCut, PowerIsConservedForEveryPlacementAndSplit) {
  const EnvMap map = make_map(256, 128, [](int x, int y) { return smooth_sky(x, y, 256, 128); });
  for (auto placement : {LightPlacement::Centroid, LightPlacement::CentroidSquared, LightPlacement::Center})
    for (auto split : {SplitRule::Median, SplitRule::Variance})
      for (int count : {1, 16, 100, 256}) {
        const auto r = median_cut(map, params(count, placement, split));
        Power sum{};
        for (const auto& l : r.lights)
          for (int c = 0; c < 3; ++c) sum[c] += l.power[c];
        EXPECT_LT(relative_error(sum, map.power()), 1e-6);
        EXPECT_LT(relative_error(r.power, map.power()), 1e-6);
      }
}

// Each region of a smooth map holds total/count of the energy, up to pixel granularity: a cut can
// only fall between rows or columns, so each cut may miss the even split by up to half a row or
// column of the region (about 1/(2 * 13) for the thin 13-row regions near the poles at 256 lights on
// 1024 x 512), and the misses of the k levels compound.
struct EnergySpread {
  double worst = 0, rms = 0;
};

EnergySpread energy_spread(int w, int count) {
  const int h = w / 2;
  const EnvMap map = make_map(w, h, [&](int x, int y) { return smooth_sky(x, y, w, h); });
  const auto r = median_cut(map, params(count));
  const double target = power_luminance(r.power, LuminanceMode::Average) / count;
  EnergySpread s;
  for (const auto& l : r.lights) {
    const double e = std::abs(l.energy - target) / target;
    s.worst = std::max(s.worst, e), s.rms += e * e;
  }
  s.rms = std::sqrt(s.rms / count);
  EXPECT_NEAR(r.energy_min, target, s.worst * target * (1 + 1e-9));
  EXPECT_NEAR(r.energy_max, target, s.worst * target * (1 + 1e-9));
  return s;
}

TEST(MedianCut, RegionsOfASmoothMapHoldEqualEnergy) {
  // Measured: 1024 x 512, 64 lights: worst 1.7%, rms 0.8%; 2048 x 1024, 256 lights: worst 1.7%,
  // rms 0.7%; 1024 x 512, 256 lights: worst 5.9%, rms 1.4%.
  const EnergySpread a = energy_spread(1024, 64);
  EXPECT_LT(a.worst, 0.025);
  const EnergySpread b = energy_spread(2048, 256);
  EXPECT_LT(b.worst, 0.025);
  const EnergySpread c = energy_spread(1024, 256);
  EXPECT_LT(c.rms, 0.02);
  EXPECT_LT(c.worst, 0.07);
}

TEST(MedianCut, OneBrightPixelGetsALightCarryingAllThePower) {
  const int w = 512, h = 256;
  for (auto [px, py] : {std::pair{100, 50}, std::pair{0, 0}, std::pair{511, 255}, std::pair{300, 128}}) {
    const EnvMap map = make_map(w, h, [&](int x, int y) { return x == px && y == py ? Rgb{500, 400, 300} : Rgb{}; });
    for (auto placement : {LightPlacement::Centroid, LightPlacement::CentroidSquared})
      for (auto split : {SplitRule::Median, SplitRule::Variance})
        for (int count : {1, 2, 64, 100, 256}) {
          SCOPED_TRACE(testing::Message() << "pixel " << px << "," << py << " count " << count << " "
                                          << enum_name(placement) << " " << enum_name(split));
          const auto r = median_cut(map, params(count, placement, split));
          int lit = 0;
          for (const auto& l : r.lights) {
            if (l.energy == 0) continue;
            ++lit;
            EXPECT_EQ(l.pixel_x, px);
            EXPECT_EQ(l.pixel_y, py);
            EXPECT_NEAR(l.u, (px + 0.5) / w, 1e-12);
            EXPECT_NEAR(l.v, (py + 0.5) / h, 1e-12);
            const Vec3 d = latlong::direction({float((px + 0.5) / w), float((py + 0.5) / h)});
            EXPECT_NEAR(dot(l.direction, d), 1.0f, 1e-6f);
            EXPECT_LT(relative_error(l.power, map.power()), 1e-6);
          }
          EXPECT_EQ(lit, 1);
        }
  }
}

// On a uniform map, latitude compensation makes regions near the poles wide and flat in pixels
// (they are narrow in longitude only in radians), regions at the equator about square.
TEST(MedianCut, RegionsNearThePolesAreWiderInPixels) {
  const int w = 1024, h = 512;
  const EnvMap map = make_map(w, h, [](int, int) { return Rgb{1, 1, 1}; });
  const auto r = median_cut(map, params(256));
  double pole_width = 0, pole_aspect = 0, equator_width = 0, equator_aspect = 0;
  int poles = 0, equators = 0;
  for (const auto& l : r.lights) {
    const Region& g = l.region;
    const double aspect = double(g.width()) / g.height();
    if (g.y0 == 0 || g.y1 == h) pole_width += g.width(), pole_aspect += aspect, ++poles;
    if (g.y0 <= h / 2 && g.y1 > h / 2) equator_width += g.width(), equator_aspect += aspect, ++equators;
  }
  ASSERT_GT(poles, 0);
  ASSERT_GT(equators, 0);
  pole_width /= poles, pole_aspect /= poles, equator_width /= equators, equator_aspect /= equators;
  RecordProperty("pole_width", std::to_string(pole_width));
  RecordProperty("equator_width", std::to_string(equator_width));
  EXPECT_GT(pole_width, 2.0 * equator_width);
  EXPECT_GT(pole_aspect, 4.0 * equator_aspect);
  EXPECT_NEAR(equator_aspect, 1.0, 0.6);
}

// Uniform 64 x 32 map: the first cut halves the width; a 32 x 32 half at the equator is as wide as it
// is tall in radians, so the next cut is horizontal at the equator.
TEST(MedianCut, PowerOfTwoCutsEveryRegionOtherCountsTheMostEnergetic) {
  const EnvMap map = make_map(64, 32, [](int, int) { return Rgb{1, 1, 1}; });
  auto regions = [&](int count) {
    const auto r = median_cut(map, params(count));
    std::vector<std::array<int, 4>> out;
    for (const auto& l : r.lights) out.push_back({l.region.x0, l.region.y0, l.region.x1, l.region.y1});
    std::sort(out.begin(), out.end());
    return out;
  };
  using V = std::vector<std::array<int, 4>>;
  EXPECT_EQ(regions(2), (V{{0, 0, 32, 32}, {32, 0, 64, 32}}));
  EXPECT_EQ(regions(4), (V{{0, 0, 32, 16}, {0, 16, 32, 32}, {32, 0, 64, 16}, {32, 16, 64, 32}}));
  const auto three = regions(3);
  ASSERT_EQ(three.size(), 3u);
  int halves = 0, quarters = 0;
  for (const auto& g : three) {
    const int area = (g[2] - g[0]) * (g[3] - g[1]);
    halves += area == 32 * 32, quarters += area == 32 * 16;
  }
  EXPECT_EQ(halves, 1);
  EXPECT_EQ(quarters, 2);
}

TEST(MedianCut, NonPowerOfTwoEnergiesFollowTheGreedyOrder) {
  const EnvMap map = make_map(256, 128, [](int x, int y) { return smooth_sky(x, y, 256, 128); });
  const auto r = median_cut(map, params(3));
  std::vector<double> e;
  for (const auto& l : r.lights) e.push_back(l.energy);
  std::sort(e.begin(), e.end());
  const double total = e[0] + e[1] + e[2];
  EXPECT_NEAR(e[0] / total, 0.25, 0.01);
  EXPECT_NEAR(e[1] / total, 0.25, 0.01);
  EXPECT_NEAR(e[2] / total, 0.5, 0.01);
}

TEST(MedianCut, CentroidPlacementsWeighByEnergyAndItsSquare) {
  // Two lit pixels on one row: weights 1 and 3 at x = 10 and 30 (pixel centres 10.5 and 30.5).
  const int w = 64, h = 32;
  const EnvMap map = make_map(w, h, [](int x, int y) {
    if (y != 7) return Rgb{};
    return x == 10 ? Rgb{1, 1, 1} : (x == 30 ? Rgb{3, 3, 3} : Rgb{});
  });
  const auto plain = median_cut(map, params(1, LightPlacement::Centroid));
  EXPECT_NEAR(plain.lights[0].u * w, (1 * 10.5 + 3 * 30.5) / 4, 1e-9);  // 25.5
  EXPECT_NEAR(plain.lights[0].v * h, 7.5, 1e-9);
  EXPECT_EQ(plain.lights[0].pixel_x, 25);
  const auto squared = median_cut(map, params(1, LightPlacement::CentroidSquared));
  EXPECT_NEAR(squared.lights[0].u * w, (1 * 10.5 + 9 * 30.5) / 10, 1e-9);  // 28.5
  EXPECT_EQ(squared.lights[0].pixel_x, 28);
  const auto centre = median_cut(map, params(1, LightPlacement::Center));
  EXPECT_NEAR(centre.lights[0].u, 0.5, 1e-12);
  EXPECT_NEAR(centre.lights[0].v, 0.5, 1e-12);
  EXPECT_NEAR(centre.lights[0].direction.x, -1.0f, 1e-6f);  // phi = pi on the equator
  EXPECT_NEAR(centre.lights[0].direction.z, 0.0f, 1e-6f);
}

// Energy in luminance: rec709 weighs green most.
TEST(MedianCut, EnergyIsTheLuminanceOfThePower) {
  const EnvMap map = make_map(64, 32, [](int, int) { return Rgb{0, 1, 0}; });
  for (auto mode : {LuminanceMode::Average, LuminanceMode::Rec709}) {
    MedianCutParams p = params(4);
    p.luminance = mode;
    const auto r = median_cut(map, p);
    double energy = 0;
    for (const auto& l : r.lights) energy += l.energy;
    const double expected = map.power().y * (mode == LuminanceMode::Average ? 1.0 / 3.0 : 0.7152);
    EXPECT_NEAR(energy, expected, 1e-6 * expected);
  }
}

TEST(MedianCut, RejectsCountsItCannotMeet) {
  const EnvMap map = make_map(8, 4, [](int, int) { return Rgb{1, 1, 1}; });
  for (int count : {0, -1, 33}) {
    try {
      median_cut(map, params(count));
      ADD_FAILURE() << "count " << count << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
    }
  }
  EXPECT_EQ(median_cut(map, params(32)).lights.size(), 32u);
}

TEST(MedianCut, ResultsAreCachedPerParameters) {
  const EnvMap map = make_map(64, 32, [](int x, int y) { return smooth_sky(x, y, 64, 32); });
  bool hit = true;
  const auto a = median_cut_cached(map, params(8), &hit);
  EXPECT_FALSE(hit);
  const auto b = median_cut_cached(map, params(8), &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(a.get(), b.get());
  const auto c = median_cut_cached(map, params(8, LightPlacement::Center), &hit);
  EXPECT_FALSE(hit);
  EXPECT_NE(a.get(), c.get());
}

TEST(MedianCut, ParameterNamesRoundTrip) {
  for (auto p : {LightPlacement::Centroid, LightPlacement::CentroidSquared, LightPlacement::Center})
    EXPECT_EQ(parse_enum<LightPlacement>(enum_name(p)), p);
  for (auto s : {SplitRule::Median, SplitRule::Variance}) EXPECT_EQ(parse_enum<SplitRule>(enum_name(s)), s);
  EXPECT_FALSE(parse_enum<LightPlacement>("centre"));
  EXPECT_FALSE(parse_enum<SplitRule>("mean"));
  EXPECT_EQ(params(64).key(), "count=64;placement=centroid;split=median;luminance=average");
}

}  // namespace
}  // namespace lp
