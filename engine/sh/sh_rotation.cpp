#include "engine/sh/sh_rotation.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/sh/gauss_legendre.hpp"

namespace lp {
namespace {

// Uniform in phi: exact for trigonometric polynomials of degree below this, 2 (kMaxShBands - 1) at most.
constexpr int kPhiSteps = 4 * kMaxShBands;

}  // namespace

ShCoefficients rotate_sh(const ShCoefficients& sh, const Rotation3& r) {
  ShCoefficients out{sh.bands, std::vector<ShRgb>(sh.rgb.size(), ShRgb{})};
  const double dphi = 2 * kPi / kPhiSteps;
  for (size_t i = 0; i < kGaussLegendre8Nodes.size(); ++i)
    for (const double sign : {-1.0, 1.0}) {
      const double z = sign * kGaussLegendre8Nodes[i], s = std::sqrt(1 - z * z);
      for (int k = 0; k < kPhiSteps; ++k) {
        const double e[3] = {s * std::cos((k + 0.5) * dphi), s * std::sin((k + 0.5) * dphi), z};
        // The old frame's direction R^T e, where f is known.
        double w[3];
        for (int a = 0; a < 3; ++a)
          w[a] = r[0][size_t(a)] * e[0] + r[1][size_t(a)] * e[1] + r[2][size_t(a)] * e[2];
        const ShRgb f = sh.evaluate(w[0], w[1], w[2]);
        const ShBasis y = sh_basis(sh.bands, e[0], e[1], e[2]);
        const double weight = kGaussLegendre8Weights[i] * dphi;
        for (size_t j = 0; j < out.rgb.size(); ++j)
          for (int c = 0; c < 3; ++c) out.rgb[j][size_t(c)] += weight * y[j] * f[size_t(c)];
      }
    }
  return out;
}

}  // namespace lp
