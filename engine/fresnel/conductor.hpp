#pragma once
// Fresnel equations for a smooth dielectric -> conductor interface: the conductor has a complex index
// eta + i k (k >= 0 absorbs), the outside medium a real index eta_i. Exact (complex Snell's law), in
// double precision; with k = 0 it is the dielectric case, total internal reflection included.
#include "engine/core/vec3.hpp"

namespace lp {

struct ConductorFresnel {
  double reflectance_s = 0, reflectance_p = 0;                                  // |r_s|^2, |r_p|^2
  double reflectance() const { return 0.5 * (reflectance_s + reflectance_p); }  // unpolarised
};

// cos_i in [0, 1] (clamped) on the outside; eta_i > 0, eta > 0, k >= 0.
ConductorFresnel fresnel_conductor_polarized(double cos_i, double eta_i, double eta, double k);

// Unpolarised reflectance, for renderers: eta and k relative to the outside medium (for air, the
// tabulated values). The sign of cos_i is ignored (a conductor reflects alike from either side).
double fresnel_conductor(double cos_i, double eta, double k);
Rgb fresnel_conductor(float cos_i, Rgb eta, Rgb k);  // per channel, computed in double

}  // namespace lp
