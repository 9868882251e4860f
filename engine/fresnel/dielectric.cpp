#include "engine/fresnel/dielectric.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/fresnel/angles.hpp"

namespace lp {

std::optional<double> transmitted_cos(double cos_i, double eta_i, double eta_t) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  // cos_t^2 = 1 - (eta_i/eta_t)^2 sin_i^2, written so that eta_t - eta_i stays exact for close indices.
  const double cos_t2 = ((eta_t - eta_i) * (eta_t + eta_i) + eta_i * eta_i * cos_i * cos_i) / (eta_t * eta_t);
  if (cos_t2 <= 0) return std::nullopt;
  return std::sqrt(cos_t2);
}

DielectricFresnel fresnel_dielectric_polarized(double cos_i, double eta_i, double eta_t) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  DielectricFresnel f;
  if (eta_i == eta_t) {  // no interface; also avoids 0/0 at grazing incidence
    f.cos_t = cos_i;
    f.t_s = f.t_p = 1;
    f.transmittance_s = f.transmittance_p = 1;
    return f;
  }
  const std::optional<double> cos_t = transmitted_cos(cos_i, eta_i, eta_t);
  if (!cos_t) {
    f.total_internal_reflection = true;
    f.r_s = f.r_p = 1;
    f.reflectance_s = f.reflectance_p = 1;
    return f;
  }
  f.cos_t = *cos_t;
  const double ni_ci = eta_i * cos_i, nt_ct = eta_t * f.cos_t;  // s polarisation
  const double nt_ci = eta_t * cos_i, ni_ct = eta_i * f.cos_t;  // p polarisation
  f.r_s = (ni_ci - nt_ct) / (ni_ci + nt_ct);
  f.r_p = (nt_ci - ni_ct) / (nt_ci + ni_ct);
  f.t_s = 2 * ni_ci / (ni_ci + nt_ct);
  f.t_p = 2 * ni_ci / (nt_ci + ni_ct);
  f.reflectance_s = f.r_s * f.r_s;
  f.reflectance_p = f.r_p * f.r_p;
  f.transmittance_s = 4 * ni_ci * nt_ct / ((ni_ci + nt_ct) * (ni_ci + nt_ct));
  f.transmittance_p = 4 * nt_ci * ni_ct / ((nt_ci + ni_ct) * (nt_ci + ni_ct));
  return f;
}

double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
  if (cos_i < 0) {
    std::swap(eta_i, eta_t);
    cos_i = -cos_i;
  }
  return fresnel_dielectric_polarized(cos_i, eta_i, eta_t).reflectance();
}

double brewster_angle_deg(double eta_i, double eta_t) {
  return degrees(std::atan2(eta_t, eta_i));
}

std::optional<double> critical_angle_deg(double eta_i, double eta_t) {
  if (eta_i <= eta_t) return std::nullopt;
  return degrees(std::asin(eta_t / eta_i));
}

}  // namespace lp
