#include "engine/fresnel/fresnel_table.hpp"

#include <cmath>
#include <cstdint>

#include "engine/core/error.hpp"
#include "engine/core/validate.hpp"
#include "engine/fresnel/angles.hpp"
#include "engine/fresnel/conductor.hpp"
#include "engine/fresnel/dielectric.hpp"
#include "engine/fresnel/schlick.hpp"

namespace lp {

std::vector<double> table_angles_deg(double step) {
  require_in("step", step, limits::kFresnelStepDeg);
  constexpr double kSnap = 1e9;  // 1e-9 degree
  std::vector<double> angles;
  for (int64_t i = 0;; ++i) {
    const double deg = std::round(static_cast<double>(i) * step * kSnap) / kSnap;
    if (deg >= 90.0 - 1.0 / kSnap) break;
    angles.push_back(deg);
  }
  angles.push_back(90.0);
  return angles;
}

DielectricTable dielectric_table(double eta_i, double eta_t, double step) {
  DielectricTable t;
  t.eta_i = eta_i;
  t.eta_t = eta_t;
  t.angles_deg = table_angles_deg(step);
  for (const double deg : t.angles_deg) {
    const double c = cos_deg(deg);
    const DielectricFresnel f = fresnel_dielectric_polarized(c, eta_i, eta_t);
    t.rs.push_back(f.reflectance_s);
    t.rp.push_back(f.reflectance_p);
    t.unpolarized.push_back(f.reflectance());
    t.schlick.push_back(fresnel_schlick(c, eta_i, eta_t));
  }
  t.r0 = schlick_r0(eta_i, eta_t);
  t.brewster_deg = brewster_angle_deg(eta_i, eta_t);
  t.critical_deg = critical_angle_deg(eta_i, eta_t);
  const SchlickMaxError e = schlick_max_error(eta_i, eta_t);
  t.schlick_max_abs_error = e.max_abs_error;
  t.schlick_max_error_angle_deg = e.angle_deg;
  return t;
}

ConductorTable conductor_table(double eta_i, const Rgb64& eta, const Rgb64& k, double step) {
  ConductorTable t;
  t.eta_i = eta_i;
  t.eta = eta;
  t.k = k;
  t.angles_deg = table_angles_deg(step);
  for (int ch = 0; ch < 3; ++ch) {
    ConductorCurves& curves = t.channels[ch];
    for (const double deg : t.angles_deg) {
      const ConductorFresnel f = fresnel_conductor_polarized(cos_deg(deg), eta_i, eta[ch], k[ch]);
      curves.rs.push_back(f.reflectance_s);
      curves.rp.push_back(f.reflectance_p);
      curves.unpolarized.push_back(f.reflectance());
    }
    t.r0[ch] = fresnel_conductor_polarized(1.0, eta_i, eta[ch], k[ch]).reflectance();
  }
  return t;
}

}  // namespace lp
