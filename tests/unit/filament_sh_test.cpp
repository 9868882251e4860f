// Filament's `sh`: the polynomial in Filament's frame equals the product's own E / pi (windowed as
// reported) in every direction; cmgen's auto window leaves no negative irradiance; the numbers match
// those Debian's cmgen 1.9.25 wrote for its generated uv2 map (tests/fuzz/corpus/ktx1), projected here
// from a lat-long of the same cube; and the text is printed as cmgen prints it.
#include "api/bake/filament_sh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "engine/image/image.hpp"
#include "engine/image/ktx1.hpp"
#include "engine/projection/cube_face.hpp"
#include "support/test_data.hpp"

namespace lp::api {
namespace {

double polynomial(const FilamentSh& sh, int rgb, double x, double y, double z) {
  const double terms[9] = {1, y, z, x, y * x, y * z, 3 * z * z - 1, z * x, x * x - y * y};
  double sum = 0;
  for (int i = 0; i < 9; ++i) sum += sh.coefficients[size_t(i)][size_t(rgb)] * terms[i];
  return sum;
}

ShCoefficients random_radiance(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0, 0.3);
  ShCoefficients c{3, std::vector<ShRgb>(9)};
  for (auto& rgb : c.rgb)
    for (double& v : rgb) v = normal(rng);
  for (double& v : c.rgb[0]) v = 2 + std::abs(v);
  return c;
}

TEST(FilamentSh, PolynomialInFilamentsFrameIsTheWindowedDiffuseRadiance) {
  const ShCoefficients radiance = random_radiance(3);
  const FilamentSh sh = filament_sh(radiance);
  std::vector<double> factors;
  for (int l = 0; l < 3; ++l) factors.push_back(filament_sh_window(l, sh.window_cutoff));
  const ShCoefficients want = scaled_by_band(sh_lambertian(radiance), factors);
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 200; ++i) {
    double x = normal(rng), y = normal(rng), z = normal(rng);
    const double r = std::sqrt(x * x + y * y + z * z);
    x /= r, y /= r, z /= r;
    const ShRgb world = want.evaluate(x, -z, y);  // Filament's (x, y, z) is the world's (x, -z, y)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(polynomial(sh, c, x, y, z), world[size_t(c)], 1e-12);
  }
}

TEST(FilamentSh, AutoWindowIsTheLargestThatLeavesNoNegativeIrradiance) {
  ShCoefficients constant{3, std::vector<ShRgb>(9)};
  constant.rgb[0] = {1, 2, 3};
  // Never negative: each channel's bisection climbs to the top of its range, and still windows.
  EXPECT_GT(filament_sh(constant).window_cutoff, 12.5);
  EXPECT_LT(filament_sh(constant).window_cutoff, 13);

  // A narrow bright lobe towards +x on a dim sky rings negative on the other side unless windowed.
  ShCoefficients lobe{3, std::vector<ShRgb>(9)};
  const ShBasis y = sh_basis(3, 1, 0, 0);
  for (int i = 0; i < 9; ++i) lobe.rgb[size_t(i)] = {50 * y[size_t(i)], 50 * y[size_t(i)], 50 * y[size_t(i)]};
  lobe.rgb[0][0] += 0.5;
  lobe.rgb[0][1] += 0.5;
  lobe.rgb[0][2] += 0.5;
  const FilamentSh sh = filament_sh(lobe);
  EXPECT_LT(sh.window_cutoff, 12);
  EXPECT_GT(sh.window_cutoff, 3);
  double lowest = 1e9;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 800; ++j) {
      const double z = 1 - 2 * (i + 0.5) / 400, s = std::sqrt(1 - z * z), phi = 2 * M_PI * (j + 0.5) / 800;
      lowest = std::min(lowest, polynomial(sh, 0, s * std::cos(phi), s * std::sin(phi), z));
    }
  EXPECT_GE(lowest, -1e-4 * sh.coefficients[0][0]);
}

// cmgen's uv2 map, face f of 16 x 16: the squares with x / 8 xor y / 8 odd in the face's colour times 5.
Image uv2_latlong(int width) {
  const Rgb colours[6] = {{1, 1, 1}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 1}};
  Image out(width, width / 2);
  for (int j = 0; j < out.height(); ++j)
    for (int i = 0; i < width; ++i) {
      const double theta = M_PI * (j + 0.5) / out.height(), phi = 2 * M_PI * (i + 0.5) / width;
      const CubeFacePoint p = cube_face_point(
          {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
      const int x = std::min(15, int((p.ab.x + 1) * 8)), y = std::min(15, int((p.ab.y + 1) * 8));
      out.set(i, j, ((x / 8) ^ (y / 8)) & 1 ? colours[p.face] * 5.0f : Rgb{});
    }
  return out;
}

// The frame, the order, the signs and the scale of the nine numbers, before windowing: cmgen run with
// --sh-window=no (cmgen_uv2_16_no_window_ibl.ktx). The window is checked against cmgen on a real map
// (tests/integration/cli_bake_filament_test.cpp): on this map, whose red channel has no linear part,
// cmgen's bound divides by zero and its cut-off is not that of the method it implements.
TEST(FilamentSh, MatchesCmgensUnwindowedNumbersForItsUv2Map) {
  const Ktx1Texture cmgen =
      read_ktx1(test::read_bytes(test::fuzz_corpus_path("ktx1", "cmgen_uv2_16_no_window_ibl.ktx")), {});
  std::istringstream text(cmgen.metadata.at("sh"));
  const FilamentSh ours = filament_sh(project_sh(uv2_latlong(2048), 3));
  const int band[9] = {0, 1, 1, 1, 2, 2, 2, 2, 2};
  for (size_t i = 0; i < 9; ++i)
    for (size_t c = 0; c < 3; ++c) {
      double theirs;
      text >> theirs;
      const double unwindowed = ours.coefficients[i][c] / filament_sh_window(band[i], ours.window_cutoff);
      // The lat-long's pixels straddle the checker's edges: 2e-3, a thousandth of the map's mean.
      EXPECT_NEAR(unwindowed, theirs, 2e-3) << "coefficient " << i << " channel " << c;
    }
}

TEST(FilamentSh, TextIsNineLinesOfThreeNumbersAsCmgenPrintsThem) {
  FilamentSh sh;
  sh.coefficients[0] = {0.719480693340302, 0.727043688297272, 0.0857467};
  sh.coefficients[1] = {-8.51958e-09, -0.6220140001, 12345.678};
  const std::string text = filament_sh_text(sh);
  EXPECT_TRUE(text.starts_with("0.719481 0.727044 0.0857467\n-8.51958e-09 -0.622014 12345.7\n0 0 0\n"))
      << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 9);
}

}  // namespace
}  // namespace lp::api
