#pragma once
// The illuminance a map gives an upward-facing surface (z up): the integral over the upper hemisphere
// (theta < pi/2) of the map's Rec. 709 luminance times cos theta. In the map's units: lux if the map is
// in cd/m^2. It is what pbrt-v4's `illuminance` parameter of an image infinite light sets, and a
// constant map of luminance Y gives pi Y.
#include "engine/envmap/envmap.hpp"

namespace lp {

// Exact over the pixel grid: each pixel a patch of constant radiance, its cos theta dOmega integrated
// in closed form over the part of its row above the horizon, (dphi / 2) (cos^2 theta_0 - cos^2 theta_1).
double upper_hemisphere_illuminance(const Image& image);
double upper_hemisphere_illuminance(const EnvMap& map);  // cached on the map

// The integral of cos theta dOmega over one pixel of row y, clipped at the horizon (0 below it).
double pixel_projected_solid_angle(int y, int width, int height);

}  // namespace lp
