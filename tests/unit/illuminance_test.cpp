// The upper-hemisphere illuminance of a map against closed forms: pi Y for a constant map, 0 for a map
// lit only below the horizon, and the integral of Y cos theta over the hemisphere (the quantity pbrt-v4's
// `illuminance` parameter of an image infinite light sets) for a map of smooth radiance.
#include "engine/envmap/illuminance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/constants.hpp"
#include "support/sunny_map.hpp"

namespace lp {
namespace {

Image constant_image(int width, int height, Rgb value) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.set(x, y, value);
  return image;
}

TEST(Illuminance, AConstantMapGivesPiTimesItsLuminance) {
  const Rgb value{2.0f, 0.5f, 0.25f};
  const double y = 0.2126 * 2.0 + 0.7152 * 0.5 + 0.0722 * 0.25;
  // Even and odd heights: with an odd one the horizon cuts the middle row.
  for (const auto& [w, h] : {std::pair{64, 32}, {7, 5}, {256, 127}, {3, 1}}) {
    const double e = upper_hemisphere_illuminance(constant_image(w, h, value));
    EXPECT_NEAR(e / (kPi * y), 1.0, 1e-9) << w << "x" << h;
  }
}

TEST(Illuminance, AMapLitOnlyBelowTheHorizonGivesNothing) {
  const Image image = test::latlong_image(128, [](Vec3 d) { return d.z < 0 ? Rgb{5, 5, 5} : Rgb{}; });
  EXPECT_EQ(upper_hemisphere_illuminance(image), 0.0);
}

TEST(Illuminance, IsTheHemisphereIntegralOfLuminanceTimesCosine) {
  // Radiance z^2 (x + 1) in every channel above the horizon: the integral of z^3 (x + 1) over the upper
  // hemisphere is pi / 2 (the x term integrates to 0). Each pixel holds the value at its centre (in
  // floats), which the grid's exact weights turn into the integral within 1e-8 already at 64 x 32.
  const auto f = [](Vec3 d) {
    const float v = d.z > 0 ? d.z * d.z * (d.x + 1) : 0.0f;
    return Rgb{v, v, v};
  };
  for (const int width : {64, 256, 1024})
    EXPECT_NEAR(upper_hemisphere_illuminance(test::latlong_image(width, f)) / (kPi / 2), 1.0, 1e-7) << width;
}

TEST(Illuminance, RowWeightsSumToPi) {
  // The projected solid angles of the upper rows add up to pi, and vanish below the horizon.
  for (const int h : {2, 9, 128}) {
    double sum = 0;
    for (int y = 0; y < h; ++y) sum += 5 * pixel_projected_solid_angle(y, 5, h);
    EXPECT_NEAR(sum, kPi, 1e-12) << h;
    EXPECT_EQ(pixel_projected_solid_angle(h - 1, 5, h), 0.0);
  }
}

}  // namespace
}  // namespace lp
