// Fresnel engine: the identities of the Fresnel equations, values for air -> glass (1.0 -> 1.45)
// computed by hand, Schlick's approximation and its error, conductors and their presets.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/fresnel/angles.hpp"
#include "engine/fresnel/conductor.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/fresnel/fresnel_table.hpp"
#include "engine/fresnel/metals.hpp"
#include "engine/fresnel/schlick.hpp"

namespace lp {
namespace {

// Pairs (eta_i, eta_t) in both directions, strong and weak contrast.
const std::vector<std::pair<double, double>> kPairs = {{1.0, 1.45},   {1.45, 1.0},   {1.0, 1.5}, {1.5, 1.0},
                                                       {1.33, 1.5},   {1.5, 1.33},   {1.0, 2.4}, {2.4, 1.0},
                                                       {1.0, 1.0001}, {1.0001, 1.0}, {0.5, 0.7}};

std::vector<double> dense_angles() {
  std::vector<double> a;
  for (int i = 0; i <= 9000; ++i) a.push_back(i * 0.01);
  return a;
}

TEST(FresnelDielectric, NormalIncidenceEqualsR0) {
  for (const auto& [ni, nt] : kPairs) {
    const DielectricFresnel f = fresnel_dielectric_polarized(1.0, ni, nt);
    const double r0 = (ni - nt) * (ni - nt) / ((ni + nt) * (ni + nt));
    EXPECT_NEAR(f.reflectance_s, r0, 1e-15) << ni << " -> " << nt;
    EXPECT_NEAR(f.reflectance_p, r0, 1e-15) << ni << " -> " << nt;
    EXPECT_NEAR(f.reflectance(), schlick_r0(ni, nt), 1e-15);
  }
}

TEST(FresnelDielectric, RpVanishesAtBrewster) {
  for (const auto& [ni, nt] : kPairs) {
    const double theta_b = brewster_angle_deg(ni, nt);
    EXPECT_NEAR(theta_b, degrees(std::atan(nt / ni)), 1e-12);
    const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(theta_b), ni, nt);
    ASSERT_FALSE(f.total_internal_reflection);  // Brewster's angle is always below the critical angle
    EXPECT_NEAR(f.r_p, 0.0, 1e-12) << ni << " -> " << nt;
    EXPECT_NEAR(f.reflectance_p, 0.0, 1e-12);
    EXPECT_GT(f.reflectance_s, 0.0);
  }
}

TEST(FresnelDielectric, ReflectancesInUnitIntervalAndSAboveP) {
  for (const auto& [ni, nt] : kPairs) {
    for (const double deg : dense_angles()) {
      const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(deg), ni, nt);
      ASSERT_GE(f.reflectance_s, 0.0);
      ASSERT_LE(f.reflectance_s, 1.0);
      ASSERT_GE(f.reflectance_p, 0.0);
      ASSERT_LE(f.reflectance_p, 1.0);
      ASSERT_GE(f.reflectance_s, f.reflectance_p) << ni << " -> " << nt << " at " << deg;
    }
  }
}

TEST(FresnelDielectric, TotalInternalReflectionPastCriticalAngle) {
  for (const auto& [ni, nt] : kPairs) {
    const auto crit = critical_angle_deg(ni, nt);
    ASSERT_EQ(crit.has_value(), ni > nt);
    if (!crit) continue;
    EXPECT_NEAR(std::sin(radians(*crit)), nt / ni, 1e-15);
    for (const double deg : dense_angles()) {
      const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(deg), ni, nt);
      if (deg > *crit + 1e-9) {
        ASSERT_TRUE(f.total_internal_reflection) << deg;
        ASSERT_EQ(f.reflectance_s, 1.0);
        ASSERT_EQ(f.reflectance_p, 1.0);
        ASSERT_EQ(f.transmittance(), 0.0);
      } else if (deg < *crit - 1e-9) {
        ASSERT_FALSE(f.total_internal_reflection) << deg;
        ASSERT_LT(f.reflectance(), 1.0);
      }
    }
    // Continuous at the critical angle: just below it R is already close to 1.
    const double below = fresnel_dielectric_polarized(cos_deg(*crit - 1e-7), ni, nt).reflectance();
    EXPECT_GT(below, 0.99) << ni << " -> " << nt;
  }
}

TEST(FresnelDielectric, GrazingIncidenceReflectsEverything) {
  for (const auto& [ni, nt] : kPairs) {
    const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(90.0), ni, nt);
    EXPECT_EQ(f.reflectance_s, 1.0) << ni << " -> " << nt;
    EXPECT_EQ(f.reflectance_p, 1.0) << ni << " -> " << nt;
  }
}

TEST(FresnelDielectric, EnergyConservedWithTransmissionFormula) {
  for (const auto& [ni, nt] : kPairs) {
    for (const double deg : dense_angles()) {
      if (deg == 90.0) continue;  // the projected-area factor below divides by cos_i
      const double ci = cos_deg(deg);
      const DielectricFresnel f = fresnel_dielectric_polarized(ci, ni, nt);
      if (f.total_internal_reflection) continue;
      // T = (eta_t cos_t)/(eta_i cos_i) |t|^2, with t from the engine, and again from the boundary
      // conditions (continuity of the tangential fields): t_s = 1 + r_s, t_p = (eta_i/eta_t)(1 + r_p).
      const double area = nt * f.cos_t / (ni * ci);
      const double ts = 1 + f.r_s, tp = ni / nt * (1 + f.r_p);
      ASSERT_NEAR(f.t_s, ts, 1e-12);
      ASSERT_NEAR(f.t_p, tp, 1e-12);
      ASSERT_NEAR(f.reflectance_s + area * ts * ts, 1.0, 1e-12) << ni << " -> " << nt << " at " << deg;
      ASSERT_NEAR(f.reflectance_p + area * tp * tp, 1.0, 1e-12) << ni << " -> " << nt << " at " << deg;
      ASSERT_NEAR(f.transmittance_s, area * ts * ts, 1e-12);
      ASSERT_NEAR(f.transmittance_p, area * tp * tp, 1e-12);
    }
  }
}

TEST(FresnelDielectric, StokesRelationForReverseDirection) {
  for (const auto& [ni, nt] : kPairs) {
    for (const double deg : dense_angles()) {
      const DielectricFresnel fwd = fresnel_dielectric_polarized(cos_deg(deg), ni, nt);
      if (fwd.total_internal_reflection || deg == 90.0) continue;
      // The same ray backwards: incident from the eta_t side at theta_t.
      const DielectricFresnel back = fresnel_dielectric_polarized(fwd.cos_t, nt, ni);
      ASSERT_FALSE(back.total_internal_reflection);
      ASSERT_NEAR(back.cos_t, cos_deg(deg), 1e-9);
      // 1e-10: near grazing r changes fast with the angle, and cos_t carries the rounding of cos_i.
      ASSERT_NEAR(fwd.r_s, -back.r_s, 1e-10) << ni << " -> " << nt << " at " << deg;
      ASSERT_NEAR(fwd.r_p, -back.r_p, 1e-10) << ni << " -> " << nt << " at " << deg;
      ASSERT_NEAR(fwd.reflectance(), back.reflectance(), 1e-10);
      // Stokes' other relation: t t' = 1 - r^2.
      ASSERT_NEAR(fwd.t_s * back.t_s, 1 - fwd.r_s * fwd.r_s, 1e-10);
      ASSERT_NEAR(fwd.t_p * back.t_p, 1 - fwd.r_p * fwd.r_p, 1e-10);
    }
  }
}

TEST(FresnelDielectric, AbelesIdentityAt45Degrees) {
  // At 45 degrees R_p = R_s^2 for any pair (Abeles 1950).
  for (const auto& [ni, nt] : kPairs) {
    const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(45.0), ni, nt);
    if (f.total_internal_reflection) continue;
    EXPECT_NEAR(f.reflectance_p, f.reflectance_s * f.reflectance_s, 1e-15) << ni << " -> " << nt;
  }
}

TEST(FresnelDielectric, AirToGlassValuesByHand) {
  // R0 = (0.45 / 2.45)^2 = 0.2025 / 6.0025 = 0.0337359433569346...
  EXPECT_NEAR(schlick_r0(1.0, 1.45), 0.0337359433569346, 1e-15);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.45), 0.0337359433569346, 1e-15);
  // Brewster: atan(1.45) = 0.96705... rad = 55.4077 degrees.
  EXPECT_NEAR(brewster_angle_deg(1.0, 1.45), 55.40771131, 1e-8);
  EXPECT_NEAR(brewster_angle_deg(1.0, 1.45), 55.40, 0.01);
  // Critical angle of glass -> air: asin(1 / 1.45) = 43.6028 degrees; none from air into glass.
  ASSERT_TRUE(critical_angle_deg(1.45, 1.0).has_value());
  EXPECT_NEAR(*critical_angle_deg(1.45, 1.0), 43.60281897, 1e-8);
  EXPECT_NEAR(*critical_angle_deg(1.45, 1.0), 43.60, 0.01);
  EXPECT_FALSE(critical_angle_deg(1.0, 1.45).has_value());
  // Glass -> air Brewster angle: atan(1 / 1.45) = 90 - 55.4077 = 34.5923 degrees.
  EXPECT_NEAR(brewster_angle_deg(1.45, 1.0), 34.59228869, 1e-8);
  // 45 degrees: cos_i = sin_i = 1/sqrt(2), eta_t cos_t = sqrt(1.45^2 - 1/2) = sqrt(1.6025), so with
  // a = sqrt(3.205) = 1.790251...: r_s = (1 - a)/(1 + a) = -0.2832187, r_p = (1.45^2 - a)/(1.45^2 + a)
  // = (2.1025 - 1.790251)/(2.1025 + 1.790251) = 0.0802128.
  const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(45.0), 1.0, 1.45);
  EXPECT_NEAR(f.r_s, -0.2832187038577636, 1e-13);
  EXPECT_NEAR(f.r_p, 0.0802128342148716, 1e-13);
  EXPECT_NEAR(f.reflectance_s, 0.0802128342148716, 1e-13);
  EXPECT_NEAR(f.reflectance_p, 0.0064340987727825, 1e-13);
  EXPECT_NEAR(f.reflectance(), 0.0433234664938270, 1e-13);
  EXPECT_NEAR(f.cos_t, std::sqrt(1.6025 / 2.1025), 1e-15);
}

TEST(FresnelDielectric, SignedCosineSwapsMedia) {
  for (const double deg : {0.0, 20.0, 40.0, 43.0, 50.0, 80.0}) {
    const double c = cos_deg(deg);
    EXPECT_EQ(fresnel_dielectric(-c, 1.0, 1.45), fresnel_dielectric(c, 1.45, 1.0)) << deg;
    EXPECT_EQ(fresnel_dielectric(c, 1.0, 1.45), fresnel_dielectric_polarized(c, 1.0, 1.45).reflectance());
  }
  EXPECT_EQ(fresnel_dielectric(-cos_deg(50.0), 1.0, 1.45), 1.0);  // inside the glass, past critical
}

TEST(FresnelDielectric, MatchedMediaHaveNoInterface) {
  for (const double deg : {0.0, 30.0, 89.9, 90.0}) {
    const DielectricFresnel f = fresnel_dielectric_polarized(cos_deg(deg), 1.3, 1.3);
    EXPECT_EQ(f.reflectance(), 0.0) << deg;
    EXPECT_EQ(f.transmittance(), 1.0) << deg;
    EXPECT_FALSE(f.total_internal_reflection);
  }
  EXPECT_NEAR(brewster_angle_deg(1.3, 1.3), 45.0, 1e-12);
  EXPECT_FALSE(critical_angle_deg(1.3, 1.3).has_value());
}

TEST(FresnelSchlick, EndPointsAndTotalInternalReflection) {
  for (const auto& [ni, nt] : kPairs) {
    EXPECT_NEAR(fresnel_schlick(1.0, ni, nt), schlick_r0(ni, nt), 1e-15);
    EXPECT_NEAR(fresnel_schlick(0.0, ni, nt), 1.0, 1e-15);
  }
  EXPECT_EQ(fresnel_schlick(cos_deg(43.7), 1.45, 1.0), 1.0);  // past the critical angle 43.6
  EXPECT_LT(fresnel_schlick(cos_deg(43.5), 1.45, 1.0), 1.0);
}

TEST(FresnelSchlick, UsesTransmittedCosineInsideDenserMedium) {
  // Schlick's formula is symmetric in the two media only through cos_t: from glass at theta_i it
  // must equal the value from air at the matching theta_t (where the exact R is also the same).
  for (const double deg : {10.0, 25.0, 40.0}) {
    const double ci = cos_deg(deg);
    const double ct = *transmitted_cos(ci, 1.45, 1.0);
    EXPECT_NEAR(fresnel_schlick(ci, 1.45, 1.0), fresnel_schlick(ct, 1.0, 1.45), 1e-15);
    // By hand at 40 degrees inside glass: sin_t = 1.45 sin 40 = 0.932042, cos_t = 0.362351,
    // R = R0 + (1 - R0)(1 - cos_t)^5 = 0.0337359 + 0.9662641 * 0.637649^5 = 0.135597.
    if (deg == 40.0) {
      const double st = 1.45 * std::sin(radians(40.0));
      const double m = 1 - std::sqrt(1 - st * st);
      EXPECT_NEAR(fresnel_schlick(ci, 1.45, 1.0), 0.0337359433569346 + 0.9662640566430654 * std::pow(m, 5),
                  1e-15);
      EXPECT_NEAR(fresnel_schlick(ci, 1.45, 1.0), 0.135597, 1e-6);
    }
  }
}

TEST(FresnelSchlick, MaxErrorIsTheMaximumOverAllAngles) {
  for (const auto& [ni, nt] : kPairs) {
    const SchlickMaxError e = schlick_max_error(ni, nt);
    ASSERT_GE(e.angle_deg, 0.0);
    ASSERT_LE(e.angle_deg, 90.0);
    const double c = cos_deg(e.angle_deg);
    // The reported error is the error at the reported angle...
    EXPECT_NEAR(e.max_abs_error,
                std::abs(fresnel_schlick(c, ni, nt) - fresnel_dielectric_polarized(c, ni, nt).reflectance()),
                1e-15);
    // ...and no angle of a finer grid than the engine's scan beats it.
    for (int i = 0; i <= 90000; ++i) {
      const double ci = cos_deg(i * 0.001);
      const double err =
          std::abs(fresnel_schlick(ci, ni, nt) - fresnel_dielectric_polarized(ci, ni, nt).reflectance());
      ASSERT_LE(err, e.max_abs_error + 1e-14) << ni << " -> " << nt << " at " << i * 0.001;
    }
  }
  // Air -> glass: Schlick is off by up to 0.0398 near 84.7 degrees (an independent scan every 0.001
  // degree in Python found 0.0398185089 at 84.691).
  const SchlickMaxError air_glass = schlick_max_error(1.0, 1.45);
  EXPECT_NEAR(air_glass.max_abs_error, 0.0398185089, 1e-8);
  EXPECT_NEAR(air_glass.angle_deg, 84.691, 0.002);
  // With cos_t inside the glass, Schlick and the exact curve both depend only on the ray, not on the
  // direction it is travelled: the worst error is the same, at the angle related by Snell's law.
  const SchlickMaxError glass_air = schlick_max_error(1.45, 1.0);
  EXPECT_NEAR(glass_air.max_abs_error, air_glass.max_abs_error, 1e-12);
  EXPECT_NEAR(1.45 * std::sin(radians(glass_air.angle_deg)), std::sin(radians(air_glass.angle_deg)), 1e-6);
}

TEST(FresnelConductor, ZeroExtinctionIsTheDielectric) {
  for (const auto& [ni, nt] : kPairs) {
    for (const double deg : dense_angles()) {
      const double c = cos_deg(deg);
      const ConductorFresnel m = fresnel_conductor_polarized(c, ni, nt, 0.0);
      const DielectricFresnel d = fresnel_dielectric_polarized(c, ni, nt);
      ASSERT_NEAR(m.reflectance_s, d.reflectance_s, 1e-12) << ni << " -> " << nt << " at " << deg;
      ASSERT_NEAR(m.reflectance_p, d.reflectance_p, 1e-12) << ni << " -> " << nt << " at " << deg;
    }
  }
}

TEST(FresnelConductor, NormalIncidenceClosedFormAndGoldIsRed) {
  // At normal incidence R = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) for every polarisation.
  const ConductorPreset& gold = lookup_metal("gold");
  // Red: n = 0.166, k = 3.15: (0.695556 + 9.9225) / (1.359556 + 9.9225) = 10.618056 / 11.282056.
  EXPECT_NEAR(fresnel_conductor_polarized(1.0, 1.0, gold.eta[0], gold.k[0]).reflectance(),
              10.618056 / 11.282056, 1e-12);
  for (const auto& name : metal_names()) {
    const ConductorPreset& m = lookup_metal(name);
    for (int ch = 0; ch < 3; ++ch) {
      const double n = m.eta[ch], k = m.k[ch];
      const ConductorFresnel f = fresnel_conductor_polarized(1.0, 1.0, n, k);
      const double expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
      EXPECT_NEAR(f.reflectance_s, expected, 1e-14) << name << " channel " << ch;
      EXPECT_NEAR(f.reflectance_p, expected, 1e-14) << name << " channel " << ch;
    }
  }
  const Rgb gold0 = fresnel_conductor(1.0f, gold.eta_rgb(), gold.k_rgb());
  EXPECT_GT(gold0.x, gold0.z + 0.4f);  // gold is yellow: red about 0.94, blue about 0.39
  EXPECT_NEAR(gold0.x, 0.9411, 1e-3);
  EXPECT_NEAR(gold0.z, 0.3856, 1e-3);
  const Rgb copper0 =
      fresnel_conductor(1.0f, lookup_metal("copper").eta_rgb(), lookup_metal("copper").k_rgb());
  EXPECT_GT(copper0.x, copper0.y);
  EXPECT_GT(copper0.y, copper0.z);
  const Rgb silver0 =
      fresnel_conductor(1.0f, lookup_metal("silver").eta_rgb(), lookup_metal("silver").k_rgb());
  EXPECT_GT(silver0.z, 0.9f);  // silver and aluminium are bright and nearly grey
  const Rgb al0 =
      fresnel_conductor(1.0f, lookup_metal("aluminium").eta_rgb(), lookup_metal("aluminium").k_rgb());
  EXPECT_NEAR(al0.x, al0.z, 0.02f);
}

TEST(FresnelConductor, BoundsOrderAndGrazing) {
  for (const auto& name : metal_names()) {
    const ConductorPreset& m = lookup_metal(name);
    for (int ch = 0; ch < 3; ++ch) {
      for (const double deg : dense_angles()) {
        const ConductorFresnel f = fresnel_conductor_polarized(cos_deg(deg), 1.0, m.eta[ch], m.k[ch]);
        ASSERT_GE(f.reflectance_p, 0.0);
        ASSERT_LE(f.reflectance_s, 1.0 + 1e-15);
        ASSERT_GE(f.reflectance_s, f.reflectance_p - 1e-15) << name << " at " << deg;
      }
      const ConductorFresnel grazing = fresnel_conductor_polarized(0.0, 1.0, m.eta[ch], m.k[ch]);
      EXPECT_NEAR(grazing.reflectance_s, 1.0, 1e-15);
      EXPECT_NEAR(grazing.reflectance_p, 1.0, 1e-15);
    }
  }
}

TEST(FresnelConductor, OutsideMediumScalesTheIndex) {
  // Gold under water (1.33) is gold in air with index (eta + i k) / 1.33.
  for (const double deg : {0.0, 30.0, 60.0, 85.0}) {
    const double c = cos_deg(deg);
    const ConductorFresnel water = fresnel_conductor_polarized(c, 1.33, 0.166, 3.15);
    const ConductorFresnel air = fresnel_conductor_polarized(c, 1.0, 0.166 / 1.33, 3.15 / 1.33);
    EXPECT_NEAR(water.reflectance_s, air.reflectance_s, 1e-14);
    EXPECT_NEAR(water.reflectance_p, air.reflectance_p, 1e-14);
  }
  EXPECT_LT(fresnel_conductor_polarized(1.0, 1.33, 0.166, 3.15).reflectance(),
            fresnel_conductor_polarized(1.0, 1.0, 0.166, 3.15).reflectance());
}

TEST(FresnelConductor, RgbMatchesDoubleAndIgnoresSign) {
  const ConductorPreset& cu = lookup_metal("copper");
  const Rgb a = fresnel_conductor(0.5f, cu.eta_rgb(), cu.k_rgb());
  const Rgb b = fresnel_conductor(-0.5f, cu.eta_rgb(), cu.k_rgb());
  EXPECT_EQ(a, b);
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(a[ch], fresnel_conductor_polarized(0.5, 1.0, cu.eta[ch], cu.k[ch]).reflectance(), 1e-6);
}

TEST(FresnelMetals, PresetsAndUnknownName) {
  EXPECT_EQ(metal_names(), (std::vector<std::string>{"gold", "silver", "copper", "aluminium"}));
  EXPECT_EQ(lookup_metal("gold").eta[0], 0.166);
  EXPECT_EQ(lookup_metal("aluminium").k[2], 5.48);
  try {
    lookup_metal("unobtainium");
    FAIL() << "no throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
    EXPECT_NE(std::string(e.what()).find("gold, silver, copper, aluminium"), std::string::npos);
  }
}

TEST(FresnelTable, Angles) {
  const std::vector<double> one = table_angles_deg(1.0);
  ASSERT_EQ(one.size(), 91u);
  for (int i = 0; i <= 90; ++i) EXPECT_EQ(one[i], i);
  EXPECT_EQ(table_angles_deg(7.0),
            (std::vector<double>{0, 7, 14, 21, 28, 35, 42, 49, 56, 63, 70, 77, 84, 90}));
  EXPECT_EQ(table_angles_deg(90.0), (std::vector<double>{0, 90}));
  EXPECT_EQ(table_angles_deg(50.0), (std::vector<double>{0, 50, 90}));
  const std::vector<double> tenth = table_angles_deg(0.1);
  ASSERT_EQ(tenth.size(), 901u);
  EXPECT_EQ(tenth[3], 0.3);
  EXPECT_EQ(tenth[899], 89.9);
  EXPECT_EQ(tenth.back(), 90.0);
  EXPECT_THROW(table_angles_deg(0.0), Error);
  EXPECT_THROW(table_angles_deg(-1.0), Error);
  EXPECT_THROW(table_angles_deg(90.5), Error);
  EXPECT_THROW(table_angles_deg(std::nan("")), Error);
}

TEST(FresnelTable, DielectricTableMatchesTheEngine) {
  const DielectricTable t = dielectric_table(1.45, 1.0, 5.0);
  ASSERT_EQ(t.angles_deg.size(), 19u);
  ASSERT_EQ(t.rs.size(), 19u);
  ASSERT_EQ(t.schlick.size(), 19u);
  EXPECT_NEAR(t.r0, 0.0337359433569346, 1e-15);
  EXPECT_NEAR(t.rs[0], t.r0, 1e-15);
  EXPECT_NEAR(t.brewster_deg, 34.59228869, 1e-8);
  ASSERT_TRUE(t.critical_deg.has_value());
  EXPECT_NEAR(*t.critical_deg, 43.60281897, 1e-8);
  for (size_t i = 0; i < t.angles_deg.size(); ++i) {
    EXPECT_EQ(t.unpolarized[i], 0.5 * (t.rs[i] + t.rp[i]));
    if (t.angles_deg[i] > 43.61) {
      EXPECT_EQ(t.unpolarized[i], 1.0);
      EXPECT_EQ(t.schlick[i], 1.0);
    }
  }
  const SchlickMaxError e = schlick_max_error(1.45, 1.0);
  EXPECT_EQ(t.schlick_max_abs_error, e.max_abs_error);
  EXPECT_EQ(t.schlick_max_error_angle_deg, e.angle_deg);
  EXPECT_LT(t.schlick_max_error_angle_deg, 43.61);
}

TEST(FresnelTable, ConductorTableGold) {
  const ConductorPreset& gold = lookup_metal("gold");
  const ConductorTable t = conductor_table(1.0, gold.eta, gold.k, 10.0);
  ASSERT_EQ(t.angles_deg.size(), 10u);
  for (int ch = 0; ch < 3; ++ch) {
    ASSERT_EQ(t.channels[ch].unpolarized.size(), 10u);
    EXPECT_NEAR(t.channels[ch].unpolarized[0], t.r0[ch], 1e-15);
    EXPECT_NEAR(t.channels[ch].unpolarized.back(), 1.0, 1e-15);
  }
  EXPECT_GT(t.r0[0], t.r0[2]);
}

}  // namespace
}  // namespace lp
