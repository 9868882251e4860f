// Spherical harmonics carried into another frame: the rotated coefficients reconstruct, at a direction e
// of the new frame, what the old ones give at R^T e, for every band.
#include "engine/sh/sh_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lp {
namespace {

ShCoefficients some_coefficients(int bands) {
  ShCoefficients sh{bands, std::vector<ShRgb>(size_t(sh_coefficient_count(bands)))};
  for (size_t j = 0; j < sh.rgb.size(); ++j)
    sh.rgb[j] = {std::sin(1.0 + double(j)), std::cos(2.0 * double(j)), 0.1 * double(j) - 0.5};
  return sh;
}

// glTF's frame from the z-up world: (x, y, z) -> (x, z, -y).
constexpr Rotation3 kToYUp = {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};

TEST(ShRotation, ReconstructsTheSameFunctionInTheNewFrame) {
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Rotation3 about_z = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  for (const Rotation3& r : {kToYUp, about_z})
    for (int bands = 1; bands <= kMaxShBands; ++bands) {
      const ShCoefficients sh = some_coefficients(bands), rotated = rotate_sh(sh, r);
      for (int k = 0; k < 20; ++k) {
        const double z = -0.95 + 0.1 * k, phi = 0.9 * k, rho = std::sqrt(1 - z * z);
        const double e[3] = {rho * std::cos(phi), rho * std::sin(phi), z};
        double w[3];
        for (size_t a = 0; a < 3; ++a) w[a] = r[0][a] * e[0] + r[1][a] * e[1] + r[2][a] * e[2];
        const ShRgb expected = sh.evaluate(w[0], w[1], w[2]), got = rotated.evaluate(e[0], e[1], e[2]);
        for (size_t ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], 1e-12) << bands << " " << k;
      }
    }
}

TEST(ShRotation, BandOneFollowsTheAxes) {
  // Y_1,-1 : Y_1,0 : Y_1,1 is y : z : x. World z (Y_1,0) becomes glTF's y (Y_1,-1).
  ShCoefficients up{2, std::vector<ShRgb>(4)};
  up.rgb[2] = {1, 2, 3};
  const ShCoefficients r = rotate_sh(up, kToYUp);
  for (size_t ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(r.rgb[1][ch], double(ch + 1), 1e-14);
    EXPECT_NEAR(r.rgb[0][ch], 0, 1e-14);
    EXPECT_NEAR(r.rgb[2][ch], 0, 1e-14);
    EXPECT_NEAR(r.rgb[3][ch], 0, 1e-14);
  }
}

}  // namespace
}  // namespace lp
