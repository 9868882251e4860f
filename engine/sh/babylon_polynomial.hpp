#pragma once
// The irradiance of a map as Babylon.js's SphericalPolynomial, the `irradiance` of its .env files.
//
// Babylon's PBR materials evaluate, by default, harmonics h_lm (its basis: ours with the Condon-Shortley
// sign on m = -1 and m = 1 of bands 1 and 2) that hold the Lambertian radiance E / pi of a white surface:
// h_lm = (A_l / pi) L_lm. It stores them as the polynomial SphericalPolynomial.FromHarmonics(h) and gets
// them back with SphericalHarmonics.FromPolynomial. FromHarmonics weighs band l by A_l / pi once more, so
// the polynomial is: its isotropic quadratic part the mean of E / pi; its linear part 2/3 of the linear
// part of E / pi; its trace-free quadratic part 1/4 of that of E / pi. (The polynomial evaluated as it
// stands, Babylon's path with useSphericalHarmonics off, is that second convolution.)
#include <array>

#include "engine/sh/sh_projection.hpp"

namespace lp {

// The fields of Babylon's SphericalPolynomial, each an RGB triple.
struct BabylonSphericalPolynomial {
  ShRgb x{}, y{}, z{}, xx{}, yy{}, zz{}, yz{}, zx{}, xy{};
  bool operator==(const BabylonSphericalPolynomial&) const = default;
};

// A rotation or reflection of directions: row i gives component i of the result.
using Matrix3 = std::array<std::array<double, 3>, 3>;

// The polynomial of the radiance `radiance` (at least 3 bands, our basis, world frame; bands above 2
// are not used) in the frame `world_to_engine` takes world directions to.
BabylonSphericalPolynomial babylon_polynomial(const ShCoefficients& radiance, const Matrix3& world_to_engine);

}  // namespace lp
