// The real SH basis against its closed forms (Sloan's table, no Condon-Shortley phase), its
// orthonormality over the sphere, and the clamped-cosine factors of Ramamoorthi and Hanrahan.
#include "engine/sh/sh_basis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/core/constants.hpp"
#include "engine/envmap/latlong.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp {
namespace {

struct Dir {
  double x, y, z;
};

std::vector<Dir> random_directions(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Dir> out;
  while (int(out.size()) < n) {
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    if (r > 1e-6) out.push_back({x / r, y / r, z / r});
  }
  return out;
}

TEST(ShBasis, BandsZeroToTwoAreTheClosedForms) {
  for (const Dir d : random_directions(50, 1)) {
    const ShBasis y = sh_basis(3, d.x, d.y, d.z);
    const double c0 = 0.5 * std::sqrt(1 / kPi), c1 = std::sqrt(3 / (4 * kPi));
    const double c2 = 0.5 * std::sqrt(15 / kPi), c20 = 0.25 * std::sqrt(5 / kPi);
    EXPECT_NEAR(y[0], c0, 1e-12);
    EXPECT_NEAR(y[1], c1 * d.y, 1e-12);
    EXPECT_NEAR(y[2], c1 * d.z, 1e-12);
    EXPECT_NEAR(y[3], c1 * d.x, 1e-12);
    EXPECT_NEAR(y[4], c2 * d.x * d.y, 1e-12);
    EXPECT_NEAR(y[5], c2 * d.y * d.z, 1e-12);
    EXPECT_NEAR(y[6], c20 * (3 * d.z * d.z - 1), 1e-12);
    EXPECT_NEAR(y[7], c2 * d.x * d.z, 1e-12);
    EXPECT_NEAR(y[8], 0.5 * c2 * (d.x * d.x - d.y * d.y), 1e-12);
    for (size_t i = 9; i < y.size(); ++i) EXPECT_EQ(y[i], 0.0);
  }
}

TEST(ShBasis, BandsThreeAndFourAtTheirClosedForms) {
  for (const Dir d : random_directions(50, 2)) {
    const ShBasis y = sh_basis(5, d.x, d.y, d.z);
    const double x = d.x, yy = d.y, z = d.z;
    EXPECT_NEAR(y[sh_index(3, -3)], 0.25 * std::sqrt(35 / (2 * kPi)) * yy * (3 * x * x - yy * yy), 1e-12);
    EXPECT_NEAR(y[sh_index(3, 0)], 0.25 * std::sqrt(7 / kPi) * z * (5 * z * z - 3), 1e-12);
    EXPECT_NEAR(y[sh_index(3, 2)], 0.25 * std::sqrt(105 / kPi) * z * (x * x - yy * yy), 1e-12);
    EXPECT_NEAR(y[sh_index(4, 0)], 3.0 / 16 * std::sqrt(1 / kPi) * (35 * z * z * z * z - 30 * z * z + 3),
                1e-12);
    EXPECT_NEAR(
        y[sh_index(4, 4)],
        3.0 / 16 * std::sqrt(35 / kPi) * (x * x * (x * x - 3 * yy * yy) - yy * yy * (3 * x * x - yy * yy)),
        1e-12);
  }
}

// The sum over a fine lat-long grid of Y_i Y_j dOmega: the identity to the grid's quadrature error.
TEST(ShBasis, OrthonormalOverTheSphere) {
  const int w = 720, h = 360;
  std::vector<double> gram(kMaxShCoefficients * kMaxShCoefficients, 0.0);
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      const Vec3 d = latlong::direction({(float(px) + 0.5f) / float(w), (float(py) + 0.5f) / float(h)});
      const ShBasis y = sh_basis(kMaxShBands, d.x, d.y, d.z);
      const double d_omega = latlong::pixel_solid_angle(py, w, h);
      for (int i = 0; i < kMaxShCoefficients; ++i)
        for (int j = 0; j < kMaxShCoefficients; ++j)
          gram[i * kMaxShCoefficients + j] += y[i] * y[j] * d_omega;
    }
  for (int i = 0; i < kMaxShCoefficients; ++i)
    for (int j = 0; j < kMaxShCoefficients; ++j)
      EXPECT_NEAR(gram[i * kMaxShCoefficients + j], i == j ? 1.0 : 0.0, 2e-4) << i << ", " << j;
}

TEST(ShBasis, CosineLobeFactorsOfRamamoorthiAndHanrahan) {
  EXPECT_DOUBLE_EQ(sh_cosine_lobe_factor(0), kPi);
  EXPECT_DOUBLE_EQ(sh_cosine_lobe_factor(1), 2 * kPi / 3);
  EXPECT_DOUBLE_EQ(sh_cosine_lobe_factor(2), kPi / 4);
  EXPECT_DOUBLE_EQ(sh_cosine_lobe_factor(3), 0.0);
  EXPECT_DOUBLE_EQ(sh_cosine_lobe_factor(4), -kPi / 24);
}

TEST(ShBasis, WindowsFallFromOneAtBandZero) {
  EXPECT_EQ(sh_window_factors(ShWindow::None, 3), (std::vector<double>{1, 1, 1}));
  const auto hann = sh_window_factors(ShWindow::Hann, 3);
  EXPECT_DOUBLE_EQ(hann[0], 1);
  EXPECT_NEAR(hann[1], 0.75, 1e-15);
  EXPECT_NEAR(hann[2], 0.25, 1e-15);
  const auto lanczos = sh_window_factors(ShWindow::Lanczos, 2);
  EXPECT_NEAR(lanczos[1], 2 / kPi, 1e-15);
}

}  // namespace
}  // namespace lp
