// Lat-long resampling keeps a constant map constant and every map's power, smaller or larger, at sizes
// that divide the map's and sizes that do not.
#include "engine/envmap/latlong_resample.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/envmap/envmap.hpp"
#include "support/constant_map.hpp"
#include "support/real_maps.hpp"

namespace lp {
namespace {

TEST(LatlongResample, AConstantMapStaysConstant) {
  const Image image = test::constant_image(60, 30, {0.5f, 2.0f, 7.0f});
  for (const auto& [w, h] : {std::pair{16, 8}, {37, 11}, {200, 100}}) {
    const Image out = resample_latlong(image, w, h);
    ASSERT_EQ(out.width(), w);
    ASSERT_EQ(out.height(), h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        EXPECT_NEAR(out.at(x, y).x, 0.5f, 1e-6f);
        EXPECT_NEAR(out.at(x, y).y, 2.0f, 1e-6f);
        EXPECT_NEAR(out.at(x, y).z, 7.0f, 1e-5f);
      }
  }
}

TEST(LatlongResample, KeepsThePowerOfARealMap) {
  const auto map = test::real_map("sunrise.exr");  // 256 x 128, a sun of a few pixels
  for (const auto& [w, h] : {std::pair{64, 32}, {100, 37}, {256, 128}, {512, 256}, {1000, 333}}) {
    const Rgb power = EnvMap::power_of(resample_latlong(map->image(), w, h));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c] / map->power()[c], 1.0, 1e-5) << w << "x" << h;
  }
}

TEST(LatlongResample, HalvingAveragesFourPixelsBySolidAngle) {
  Image image(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) image.set(x, y, Rgb{1, 1, 1} * float(y + 1));
  const Image out = resample_latlong(image, 2, 2);
  // Rows 0 and 1 span theta 0..pi/4 and pi/4..pi/2: solid angles in the ratio (1 - cos 45) : cos 45.
  const double a = 1 - std::sqrt(0.5), b = std::sqrt(0.5);
  EXPECT_NEAR(out.at(0, 0).x, (1 * a + 2 * b) / (a + b), 1e-6);
  EXPECT_NEAR(out.at(1, 1).x, (3 * b + 4 * a) / (a + b), 1e-6);
}

}  // namespace
}  // namespace lp
