#include "engine/fresnel/conductor.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace lp {

ConductorFresnel fresnel_conductor_polarized(double cos_i, double eta_i, double eta, double k) {
  const double c = std::clamp(cos_i, 0.0, 1.0);
  if (k == 0 && eta == eta_i) return {};  // no interface; also avoids 0/0 at grazing incidence
  // With N = eta + i k and A = eta_i (n cos_t) = sqrt(N^2 - eta_i^2 sin_i^2), n = N / eta_i:
  //   r_s = (eta_i cos_i - A) / (eta_i cos_i + A),  r_p = (N^2 cos_i - eta_i A) / (N^2 cos_i + eta_i A).
  // The principal root has Im >= 0: the transmitted wave decays (for k = 0 past the critical angle it
  // is evanescent and |r| = 1). The radicand is formed as in transmitted_cos, exact for close indices.
  const std::complex<double> n2(eta * eta - k * k, 2 * eta * k);
  const std::complex<double> a = std::sqrt(
      std::complex<double>((eta - eta_i) * (eta + eta_i) - k * k + eta_i * eta_i * c * c, n2.imag()));
  // |r|^2 as |numerator|^2 / |denominator|^2: no complex division (a library call handling infinities).
  const auto reflectance = [](std::complex<double> num, std::complex<double> den) {
    return std::norm(num) / std::norm(den);
  };
  return {reflectance(eta_i * c - a, eta_i * c + a), reflectance(n2 * c - eta_i * a, n2 * c + eta_i * a)};
}

double fresnel_conductor(double cos_i, double eta, double k) {
  return fresnel_conductor_polarized(std::abs(cos_i), 1.0, eta, k).reflectance();
}

Rgb fresnel_conductor(float cos_i, Rgb eta, Rgb k) {
  const auto channel = [&](float e, float kk) { return static_cast<float>(fresnel_conductor(cos_i, e, kk)); };
  return {channel(eta.x, k.x), channel(eta.y, k.y), channel(eta.z, k.z)};
}

}  // namespace lp
