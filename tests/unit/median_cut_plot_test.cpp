#include "engine/mediancut/median_cut_plot.hpp"

#include <gtest/gtest.h>

#include <array>

namespace lp {
namespace {

std::array<int, 3> pixel(const std::vector<uint8_t>& rgb, int width, int x, int y) {
  const uint8_t* p = &rgb[(size_t(y) * width + x) * 3];
  return {p[0], p[1], p[2]};
}

// A uniform 64 x 32 map cut in four: cuts at column 32 and row 16 (see MedianCut tests).
struct Quadrants : testing::Test {
  EnvMap map{[] {
    Image image(64, 32);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 64; ++x) image.set(x, y, {0.5f, 0.5f, 0.5f});
    return image;
  }()};
  MedianCutResult result = [this] {
    MedianCutParams p;
    p.count = 4;
    p.placement = LightPlacement::Center;
    return median_cut(map, p);
  }();
};

TEST_F(Quadrants, RegionsShowCutsInGreenAndLightsInRed) {
  const auto rgb = plot_median_cut(map.image(), result, MedianCutStyle::Regions, {});
  ASSERT_EQ(rgb.size(), 64u * 32 * 3);
  const std::array<int, 3> green{0, 255, 0}, red{255, 0, 0}, grey{188, 188, 188};  // sRGB(0.5) = 188
  EXPECT_EQ(pixel(rgb, 64, 32, 3), green);
  EXPECT_EQ(pixel(rgb, 64, 5, 16), green);
  EXPECT_EQ(pixel(rgb, 64, 0, 0), grey);   // the map's own edges are not cuts
  EXPECT_EQ(pixel(rgb, 64, 63, 31), grey);
  EXPECT_EQ(pixel(rgb, 64, 31, 3), grey);  // cuts are one pixel wide
  EXPECT_EQ(pixel(rgb, 64, 33, 3), grey);
  // Centre placement: the lights sit at (16, 8), (48, 8), (16, 24), (48, 24); 512 pixels per region
  // gives 5 x 5 dots.
  EXPECT_EQ(median_cut_dot_half_size(64 * 32, 4), 2);
  EXPECT_EQ(median_cut_dot_half_size(64 * 32, 8), 1);
  for (auto [x, y] : {std::pair{16, 8}, std::pair{48, 24}, std::pair{18, 10}, std::pair{46, 22}})
    EXPECT_EQ(pixel(rgb, 64, x, y), red) << x << "," << y;
  EXPECT_EQ(pixel(rgb, 64, 19, 8), grey);
}

TEST_F(Quadrants, LightsAreDotsOnBlackScaledToTheBrightest) {
  const auto rgb = plot_median_cut(map.image(), result, MedianCutStyle::Lights, {});
  int lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) lit += pixel(rgb, 64, x, y) != std::array<int, 3>{0, 0, 0};
  EXPECT_EQ(lit, 4 * 25);
  // Four equal grey lights: each is the brightest, so each is white at exposure 0.
  EXPECT_EQ(pixel(rgb, 64, 16, 8), (std::array<int, 3>{255, 255, 255}));
  // One stop down, 0.5 in sRGB.
  const auto darker = plot_median_cut(map.image(), result, MedianCutStyle::Lights, {-1.0f, std::nullopt});
  EXPECT_EQ(pixel(darker, 64, 48, 24), (std::array<int, 3>{188, 188, 188}));
}

TEST(MedianCutPlot, StyleNamesRoundTrip) {
  for (auto s : {MedianCutStyle::Regions, MedianCutStyle::Lights})
    EXPECT_EQ(parse_enum<MedianCutStyle>(enum_name(s)), s);
  EXPECT_FALSE(parse_enum<MedianCutStyle>("dots"));
}

}  // namespace
}  // namespace lp
