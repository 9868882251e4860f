#pragma once
// Fresnel reflectance tables over incidence angles 0..90 degrees, as served by /api/v1/fresnel.
#include <array>
#include <optional>
#include <vector>

#include "engine/fresnel/metals.hpp"

namespace lp {

// 0, step, 2 step, ... below 90, then 90 itself (so the last gap is shorter when step does not divide
// 90). Angles are rounded to 1e-9 degree, so step 0.1 gives 0.3 and not 0.30000000000000004.
// Throws lp::Error(InvalidArgument) for a step outside limits::kFresnelStepDeg.
std::vector<double> table_angles_deg(double step);

struct DielectricTable {
  double eta_i = 1, eta_t = 1;
  std::vector<double> angles_deg;
  std::vector<double> rs, rp, unpolarized, schlick;  // reflectances per angle
  double r0 = 0;                                     // Schlick's R0 (the exact normal-incidence value)
  double brewster_deg = 0;
  std::optional<double> critical_deg;
  double schlick_max_abs_error = 0;  // over the continuous range 0..90, see schlick_max_error
  double schlick_max_error_angle_deg = 0;
};

// eta_i, eta_t > 0; step as for table_angles_deg.
DielectricTable dielectric_table(double eta_i, double eta_t, double step);

struct ConductorCurves {
  std::vector<double> rs, rp, unpolarized;
};

struct ConductorTable {
  double eta_i = 1;
  Rgb64 eta{}, k{};
  std::vector<double> angles_deg;
  std::array<ConductorCurves, 3> channels;  // r, g, b
  Rgb64 r0{};                               // normal-incidence reflectance per channel
};

// eta_i > 0 (the outside medium), eta > 0 and k >= 0 per channel; step as for table_angles_deg.
ConductorTable conductor_table(double eta_i, const Rgb64& eta, const Rgb64& k, double step);

}  // namespace lp
