#pragma once
// Measured complex indices of a few metals at one red, one green and one blue wavelength, for the
// Fresnel tables and the renderer's conductor material. See metals.cpp for the source of the values.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/vec3.hpp"

namespace lp {

using Rgb64 = std::array<double, 3>;  // r, g, b

// The wavelengths (nm) at which the presets' values were measured, red, green, blue.
inline constexpr Rgb64 kMetalWavelengthsNm = {652.548279, 551.040771, 450.851562};

struct ConductorPreset {
  std::string_view name;
  Rgb64 eta;  // real part of the index
  Rgb64 k;    // extinction coefficient

  Rgb eta_rgb() const { return {float(eta[0]), float(eta[1]), float(eta[2])}; }
  Rgb k_rgb() const { return {float(k[0]), float(k[1]), float(k[2])}; }
};

// "gold", "silver", "copper", "aluminium", in that order.
const std::vector<std::string>& metal_names();
// Throws lp::Error(InvalidArgument) for an unknown name.
const ConductorPreset& lookup_metal(std::string_view name);

}  // namespace lp
