#pragma once
// Real spherical harmonics, orthonormal over the sphere (the integral of Y_lm^2 is 1), in the world frame
// of the lat-long convention: z up, theta from +z, phi from +x toward +y. Without the Condon-Shortley
// phase, so that band 1 is (Y_1-1, Y_10, Y_11) = sqrt(3 / (4 pi)) (y, z, x), as in Ramamoorthi and
// Hanrahan (2001) and Sloan's "Stupid Spherical Harmonics Tricks":
//   m > 0: Y_lm = sqrt(2) K_lm cos(m phi) P_l^m(cos theta)
//   m = 0: Y_l0 = K_l0 P_l^0(cos theta)
//   m < 0: Y_lm = sqrt(2) K_l|m| sin(|m| phi) P_l^|m|(cos theta)
// with K_lm = sqrt((2l + 1) / (4 pi) * (l - m)! / (l + m)!). Coefficient l, m sits at index l (l + 1) + m.
#include <array>

#include "engine/core/limits.hpp"

namespace lp {

inline constexpr int kMaxShBands = limits::kShBands.max;
inline constexpr int kMaxShCoefficients = kMaxShBands * kMaxShBands;

constexpr int sh_index(int l, int m) {
  return l * (l + 1) + m;
}
constexpr int sh_coefficient_count(int bands) {
  return bands * bands;
}

using ShBasis = std::array<double, kMaxShCoefficients>;

// Y_lm of the first `bands` bands at the unit direction (x, y, z); the rest of the array is 0.
ShBasis sh_basis(int bands, double x, double y, double z);

// The normalisation K_lm (m >= 0) and the associated Legendre polynomials P_l^m(z) for l, m < bands,
// at [sh_index(l, m)] (m >= 0 only; no Condon-Shortley phase). Exposed for the projection's row sums.
double sh_normalisation(int l, int m);
ShBasis sh_legendre(int bands, double z);

}  // namespace lp
