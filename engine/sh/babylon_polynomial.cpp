#include "engine/sh/babylon_polynomial.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"
#include "engine/sh/sh_basis.hpp"

namespace lp {

namespace {

// E / pi of one channel as m + b . n + n^T T n on the unit sphere, T trace-free.
struct Quadratic {
  double m = 0;
  std::array<double, 3> b{};
  Matrix3 t{};
};

Quadratic lambertian_form(const ShCoefficients& radiance, int channel) {
  const auto c = [&](int l, int m) { return radiance.rgb[size_t(sh_index(l, m))][size_t(channel)]; };
  // The basis of sh_basis.hpp written out for bands 0 to 2, each band weighed by A_l / pi.
  const double k0 = 0.5 * std::sqrt(1 / kPi), k1 = std::sqrt(3 / (4 * kPi)) * 2 / 3;
  const double k2 = 0.5 * std::sqrt(15 / kPi) / 4, k20 = 0.25 * std::sqrt(5 / kPi) / 4,
               k22 = 0.25 * std::sqrt(15 / kPi) / 4;
  Quadratic q;
  q.m = k0 * c(0, 0);
  q.b = {k1 * c(1, 1), k1 * c(1, -1), k1 * c(1, 0)};
  // k20 (3 z^2 - 1) = k20 (2 z^2 - x^2 - y^2) on the sphere; k22 (x^2 - y^2); k2 xy, k2 yz, k2 xz.
  q.t[0][0] = -k20 * c(2, 0) + k22 * c(2, 2);
  q.t[1][1] = -k20 * c(2, 0) - k22 * c(2, 2);
  q.t[2][2] = 2 * k20 * c(2, 0);
  q.t[0][1] = q.t[1][0] = k2 * c(2, -2) / 2;
  q.t[1][2] = q.t[2][1] = k2 * c(2, -1) / 2;
  q.t[0][2] = q.t[2][0] = k2 * c(2, 1) / 2;
  return q;
}

// The same function in the frame of `r` (n' = r n): b' = r b, T' = r T r^T.
Quadratic transformed(const Quadratic& q, const Matrix3& r) {
  Quadratic out;
  out.m = q.m;
  for (size_t i = 0; i < 3; ++i)
    for (size_t k = 0; k < 3; ++k) out.b[i] += r[i][k] * q.b[k];
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j)
      for (size_t k = 0; k < 3; ++k)
        for (size_t l = 0; l < 3; ++l) out.t[i][j] += r[i][k] * q.t[k][l] * r[j][l];
  return out;
}

}  // namespace

BabylonSphericalPolynomial babylon_polynomial(const ShCoefficients& radiance,
                                              const Matrix3& world_to_engine) {
  if (radiance.bands < 3) throw Error(ErrorKind::InvalidArgument, "the Babylon polynomial needs 3 SH bands");
  BabylonSphericalPolynomial p;
  for (int ch = 0; ch < 3; ++ch) {
    const Quadratic q = transformed(lambertian_form(radiance, ch), world_to_engine);
    const size_t c = size_t(ch);
    // FromHarmonics's second A_l / pi: 2/3 on band 1, 1/4 on band 2.
    p.x[c] = q.b[0] * 2 / 3, p.y[c] = q.b[1] * 2 / 3, p.z[c] = q.b[2] * 2 / 3;
    p.xx[c] = q.m + q.t[0][0] / 4, p.yy[c] = q.m + q.t[1][1] / 4, p.zz[c] = q.m + q.t[2][2] / 4;
    p.xy[c] = 2 * q.t[0][1] / 4, p.yz[c] = 2 * q.t[1][2] / 4, p.zx[c] = 2 * q.t[2][0] / 4;
  }
  return p;
}

}  // namespace lp
