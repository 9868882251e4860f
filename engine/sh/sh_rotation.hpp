#pragma once
// Spherical harmonics in another frame: the coefficients of f(R^T e), e a direction of the new frame,
// for R the rotation taking a direction of the old frame into the new one (a bake target's frame:
// api/bake/bake_manifest.hpp's world_to_engine).
#include <array>

#include "engine/sh/sh_projection.hpp"

namespace lp {

using Rotation3 = std::array<std::array<double, 3>, 3>;  // rows: new axis i in old coordinates

// Exact to rounding: each band is projected by a product rule (Gauss-Legendre in z, uniform in phi)
// that integrates the products of two harmonics of up to kMaxShBands bands exactly.
ShCoefficients rotate_sh(const ShCoefficients& sh, const Rotation3& rotation);

}  // namespace lp
