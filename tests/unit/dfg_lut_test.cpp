// The split-sum DFG table against analytic values (a mirror, the white-furnace total), a brute-force
// quadrature of the GGX lobe, and its two layouts.
#include "engine/ibl/dfg_lut.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/bsdf/microfacet.hpp"
#include "engine/core/constants.hpp"

namespace lp {
namespace {

TEST(DfgLut, AtRoughnessZeroAndNormalIncidenceScalePlusBiasIsOne) {
  const DfgValue v = dfg(1.0, 0.0, false);
  EXPECT_DOUBLE_EQ(v.x, 1.0);
  EXPECT_DOUBLE_EQ(v.y, 0.0);
  const DfgValue ms = dfg(1.0, 0.0, true);
  EXPECT_DOUBLE_EQ(ms.x, 0.0);
  EXPECT_DOUBLE_EQ(ms.y, 1.0);
}

TEST(DfgLut, AMirrorSplitsBySchlicksFactor) {
  for (double mu : {0.1, 0.5, 0.9}) {
    const DfgValue v = dfg(mu, 0.0, false);
    EXPECT_NEAR(v.y, std::pow(1 - mu, 5), 1e-7);
    EXPECT_NEAR(v.x + v.y, 1.0, 1e-12);
  }
}

// The GGX reflection with F = 1 and F = Fc integrated over a fine (theta, phi) grid of incoming
// directions: D G / (4 mu) per unit solid angle (the cosine of wi is inside Ggx::reflection).
DfgValue brute_force(double mu, double roughness) {
  const render::Ggx ggx{float(roughness * roughness)};
  const Vec3 wo{float(std::sqrt(1 - mu * mu)), 0, float(mu)};
  const int nt = 1000, np = 1000;
  double total = 0, bias = 0;
  for (int i = 0; i < nt; ++i) {
    const double t0 = 0.5 * kPi * i / nt, t1 = 0.5 * kPi * (i + 1) / nt, t = 0.5 * (t0 + t1);
    const double d_omega = (std::cos(t0) - std::cos(t1)) * 2 * kPi / np;
    for (int j = 0; j < np; ++j) {
      const double p = 2 * kPi * (j + 0.5) / np;
      const Vec3 wi{float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
      const Vec3 h = normalize(wo + wi);
      const double f = ggx.reflection(wo, wi, h) * d_omega;
      total += f;
      bias += f * std::pow(1 - double(dot(wo, h)), 5);
    }
  }
  return {total - bias, bias};
}

TEST(DfgLut, MatchesABruteForceQuadratureOfTheLobe) {
  for (double roughness : {0.3, 0.6, 1.0})
    for (double mu : {0.2, 0.5, 0.95}) {
      const DfgValue v = dfg(mu, roughness, false), b = brute_force(mu, roughness);
      EXPECT_NEAR(v.x, b.x, 2e-3) << "roughness " << roughness << ", n.v " << mu;
      EXPECT_NEAR(v.y, b.y, 2e-3) << "roughness " << roughness << ", n.v " << mu;
    }
}

TEST(DfgLut, TheMultiscatterLayoutIsBiasAndTotal) {
  const DfgValue single = dfg(0.4, 0.7, false), ms = dfg(0.4, 0.7, true);
  EXPECT_DOUBLE_EQ(ms.x, single.y);
  EXPECT_DOUBLE_EQ(ms.y, single.x + single.y);
  EXPECT_LT(ms.y, 1.0);  // a rough lobe loses energy to single scattering
}

TEST(DfgLut, TexelsAtTheirCentres) {
  const DfgLut lut = make_dfg_lut(16, false);
  ASSERT_EQ(lut.texels.size(), 256u);
  const DfgValue corner = dfg(15.5 / 16, 0.5 / 16, false);
  EXPECT_DOUBLE_EQ(lut.at(15, 0).x, corner.x);
  EXPECT_NEAR(lut.at(15, 0).x + lut.at(15, 0).y, 1.0, 1e-3);
  EXPECT_LT(lut.at(8, 15).x + lut.at(8, 15).y, lut.at(8, 0).x + lut.at(8, 0).y);
  EXPECT_EQ(dfg_lut_cached(16, false).get(), dfg_lut_cached(16, false).get());
}

}  // namespace
}  // namespace lp
