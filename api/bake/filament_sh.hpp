#pragma once
// The `sh` of a Filament image-based light: what cmgen writes into NAME_ibl.ktx and Filament's
// IndirectLight takes as its irradiance. Its nine RGB numbers are the coefficients of the diffuse
// radiance of a white Lambertian surface, E(n) / pi, as a polynomial of the normal n in Filament's frame,
// in the order its shader sums them:
//   1, n.y, n.z, n.x, n.y n.x, n.y n.z, 3 n.z^2 - 1, n.z n.x, n.x^2 - n.y^2
// (cmgen: CubemapSH::computeSH of the irradiance, windowSH, preprocessSHForShader). The irradiance's
// bands are first windowed as cmgen's default --sh-window=auto does (Sloan, "Deringing Spherical
// Harmonics"): each band l scaled by sinc(pi l / w)^4, w the largest cut-off in bands (bisected from 13
// down to 3 to a tenth of a band, the smallest over the channels) that leaves no channel negative.
#include <array>
#include <string>

#include "engine/sh/sh_projection.hpp"

namespace lp::api {

struct FilamentSh {
  std::array<ShRgb, 9> coefficients{};
  double window_cutoff = 0;  // w, in bands
};

// From the radiance's first 3 bands in the world frame (z up); the frame of the result is Filament's,
// where a world direction (x, y, z) is (x, z, -y) (engine/projection/cube_face.hpp).
FilamentSh filament_sh(const ShCoefficients& radiance);

// The metadata value, as cmgen prints it: per coefficient "r g b\n", each number as a C++ stream prints
// a float by default (6 significant digits).
std::string filament_sh_text(const FilamentSh& sh);

// cmgen's sinc window of band l for a cut-off of w bands.
double filament_sh_window(int l, double cutoff);

}  // namespace lp::api
