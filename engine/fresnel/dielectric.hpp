#pragma once
// Fresnel equations for a smooth interface between two dielectrics (real indices eta_i -> eta_t), in
// double precision. Conventions (Hecht): amplitude coefficients
//   r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)
//   r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)
// reflectances R = r^2, unpolarised (R_s + R_p) / 2. Past the critical angle (only when eta_i > eta_t)
// there is total internal reflection: R_s = R_p = 1, T = 0. Matched media (eta_i == eta_t) have no
// interface: R = 0 and T = 1 at every angle, grazing included.
#include <optional>

namespace lp {

struct DielectricFresnel {
  bool total_internal_reflection = false;  // cos_i at or past the critical angle
  double cos_t = 0;                        // cosine of the transmission angle (0 under TIR)
  // Amplitude coefficients. Under TIR the true ones are complex with modulus 1: here r_s = r_p = 1
  // (the modulus) and t_s = t_p = 0.
  double r_s = 0, r_p = 0;
  double t_s = 0, t_p = 0;
  double reflectance_s = 0, reflectance_p = 0;      // |r|^2
  double transmittance_s = 0, transmittance_p = 0;  // (eta_t cos_t)/(eta_i cos_i) |t|^2 = 1 - R

  double reflectance() const { return 0.5 * (reflectance_s + reflectance_p); }  // unpolarised
  double transmittance() const { return 0.5 * (transmittance_s + transmittance_p); }
};

// Cosine of the transmission angle by Snell's law, nullopt under total internal reflection (at or past
// the critical angle). cos_i in [0, 1] is clamped. Accurate near grazing and for close indices.
std::optional<double> transmitted_cos(double cos_i, double eta_i, double eta_t);

// Everything about one angle. cos_i is the cosine of the incidence angle on the eta_i side, in [0, 1]
// (clamped). eta_i, eta_t > 0.
DielectricFresnel fresnel_dielectric_polarized(double cos_i, double eta_i, double eta_t);

// Unpolarised reflectance, for renderers. cos_i is the cosine between the incident direction (pointing
// away from the surface) and the normal on the eta_i side; a negative cos_i means the direction is on the
// other side, so the media swap: fresnel_dielectric(-c, a, b) == fresnel_dielectric(c, b, a).
double fresnel_dielectric(double cos_i, double eta_i, double eta_t);

// Brewster's angle atan(eta_t / eta_i) in degrees, where R_p = 0. For matched media it is formally 45
// degrees (every reflectance is 0 there anyway).
double brewster_angle_deg(double eta_i, double eta_t);
// Critical angle asin(eta_t / eta_i) in degrees when eta_i > eta_t, else nullopt (no TIR).
std::optional<double> critical_angle_deg(double eta_i, double eta_t);

}  // namespace lp
