// The spherical polynomial of a .env: read back as Babylon.js does (SphericalHarmonics.FromPolynomial,
// then the harmonics its PBR shader sums, their constants copied from @babylonjs/core), it gives the
// Lambertian radiance E / pi of our SH at every normal, in the engine frame the matrix names.
#include "engine/sh/babylon_polynomial.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {
namespace {

// Babylon's harmonics path for one channel: FromPolynomial, preScaleForRendering,
// computeEnvironmentIrradiance.
double babylon_irradiance(const BabylonSphericalPolynomial& p, int c, double x, double y, double z) {
  const size_t i = size_t(c);
  const double l00 = (p.xx[i] * 0.376127 + p.yy[i] * 0.376127 + p.zz[i] * 0.376126) * kPi;
  const double l1_1 = -p.y[i] * 0.977204 * kPi, l10 = p.z[i] * 0.977204 * kPi, l11 = -p.x[i] * 0.977204 * kPi;
  const double l2_2 = p.xy[i] * 1.16538 * kPi, l2_1 = -p.yz[i] * 1.16538 * kPi;
  const double l20 = (p.zz[i] * 1.34567 - p.xx[i] * 0.672834 - p.yy[i] * 0.672834) * kPi;
  const double l21 = -p.zx[i] * 1.16538 * kPi, l22 = (p.xx[i] * 1.16538 - p.yy[i] * 1.16538) * kPi;
  const double s1 = std::sqrt(3 / (4 * kPi)), s2 = std::sqrt(15 / (4 * kPi));
  return l00 * std::sqrt(1 / (4 * kPi)) - l1_1 * s1 * y + l10 * s1 * z - l11 * s1 * x + l2_2 * s2 * x * y -
         l2_1 * s2 * y * z + l20 * std::sqrt(5 / (16 * kPi)) * (3 * z * z - 1) - l21 * s2 * x * z +
         l22 * std::sqrt(15 / (16 * kPi)) * (x * x - y * y);
}

ShCoefficients some_radiance() {
  ShCoefficients sh;
  sh.bands = 3;
  for (int k = 0; k < 9; ++k)
    sh.rgb.push_back({1.0 / (k + 1), 0.3 * std::sin(k + 1.0), 0.2 * std::cos(2.0 * k)});
  sh.rgb[0] = {2.0, 1.5, 1.0};
  return sh;
}

void expect_lambertian(const Matrix3& world_to_engine) {
  const ShCoefficients radiance = some_radiance();
  const ShCoefficients lambertian = sh_lambertian(radiance);
  const BabylonSphericalPolynomial p = babylon_polynomial(radiance, world_to_engine);
  for (int k = 0; k < 40; ++k) {
    const double theta = std::acos(1 - 2 * (k + 0.5) / 40), phi = k * 2.39996;
    const double w[3] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    double d[3] = {0, 0, 0};
    for (size_t i = 0; i < 3; ++i)
      for (size_t j = 0; j < 3; ++j) d[i] += world_to_engine[i][j] * w[j];
    const ShRgb expected = lambertian.evaluate(w[0], w[1], w[2]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(babylon_irradiance(p, c, d[0], d[1], d[2]), expected[size_t(c)], 2e-5) << k << " " << c;
  }
}

TEST(BabylonPolynomial, GivesTheLambertianRadianceInTheEngineFrame) {
  expect_lambertian({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  expect_lambertian({{{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}});  // z-up world to Babylon's left-handed y-up
  const double c = std::cos(0.7), s = std::sin(0.7);
  expect_lambertian({{{c, -s, 0}, {s * 0.6, c * 0.6, -0.8}, {s * 0.8, c * 0.8, 0.6}}});
}

TEST(BabylonPolynomial, AConstantMapIsItsIsotropicPart) {
  ShCoefficients sh;
  sh.bands = 3;
  sh.rgb.assign(9, {0, 0, 0});
  sh.rgb[0] = {2 * std::sqrt(kPi), 0, 0};  // radiance 1: E / pi = 1
  const BabylonSphericalPolynomial p = babylon_polynomial(sh, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  EXPECT_NEAR(p.xx[0], 1, 1e-12);
  EXPECT_NEAR(p.yy[0], 1, 1e-12);
  EXPECT_NEAR(p.zz[0], 1, 1e-12);
  EXPECT_EQ(p.x[0], 0);
  EXPECT_EQ(p.xy[0], 0);
}

}  // namespace
}  // namespace lp
