#include "engine/sh/sh_basis.hpp"

#include <cmath>

#include "engine/core/constants.hpp"

namespace lp {

double sh_normalisation(int l, int m) {
  double ratio = 1;  // (l - m)! / (l + m)!
  for (int k = l - m + 1; k <= l + m; ++k) ratio /= k;
  return std::sqrt((2 * l + 1) / (4 * kPi) * ratio);
}

// P_m^m = (2m - 1)!! s^m, P_{m+1}^m = (2m + 1) z P_m^m, then the recurrence in l.
ShBasis sh_legendre(int bands, double z) {
  ShBasis p{};
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  double pmm = 1;
  for (int m = 0; m < bands; ++m) {
    if (m > 0) pmm *= (2 * m - 1) * s;
    p[sh_index(m, m)] = pmm;
    if (m + 1 < bands) p[sh_index(m + 1, m)] = (2 * m + 1) * z * pmm;
    for (int l = m + 2; l < bands; ++l)
      p[sh_index(l, m)] =
          ((2 * l - 1) * z * p[sh_index(l - 1, m)] - (l + m - 1) * p[sh_index(l - 2, m)]) / (l - m);
  }
  return p;
}

ShBasis sh_basis(int bands, double x, double y, double z) {
  const ShBasis p = sh_legendre(bands, z);
  const double phi = std::atan2(y, x);
  ShBasis out{};
  for (int l = 0; l < bands; ++l) {
    out[sh_index(l, 0)] = sh_normalisation(l, 0) * p[sh_index(l, 0)];
    for (int m = 1; m <= l; ++m) {
      const double k = std::sqrt(2.0) * sh_normalisation(l, m) * p[sh_index(l, m)];
      out[sh_index(l, m)] = k * std::cos(m * phi);
      out[sh_index(l, -m)] = k * std::sin(m * phi);
    }
  }
  return out;
}

}  // namespace lp
