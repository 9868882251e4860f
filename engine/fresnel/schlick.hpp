#pragma once
// Schlick's approximation of the unpolarised dielectric reflectance,
//   R(theta) ~ R0 + (1 - R0) (1 - cos)^5,  R0 = ((eta_i - eta_t) / (eta_i + eta_t))^2,
// in its correct form for both directions: cos is the cosine of the incidence angle when eta_i <= eta_t
// and of the transmission angle when eta_i > eta_t (then 1 past the critical angle). For matched media
// R0 = 0 but the formula still rises to 1 at grazing incidence, while the exact reflectance is 0: the
// formula is reported as it is.
namespace lp {

double schlick_r0(double eta_i, double eta_t);

// cos_i in [0, 1] (clamped) on the eta_i side.
double fresnel_schlick(double cos_i, double eta_i, double eta_t);

struct SchlickMaxError {
  double max_abs_error = 0;  // max over theta in [0, 90] of |Schlick - exact unpolarised|
  double angle_deg = 0;      // where it occurs
};

// Found over the continuous range 0..90 degrees, not only at some table's angles: a scan every 0.01
// degree, then golden-section refinement around the best scan point (angle to about 1e-9 degree).
SchlickMaxError schlick_max_error(double eta_i, double eta_t);

}  // namespace lp
