#pragma once
// A sun taken out of a map (engine/sun/sun_extraction.hpp): where it is, how large, how bright.
#include <cstdint>

#include "engine/core/vec3.hpp"
#include "engine/mediancut/light_placement.hpp"
#include "engine/sun/cone_pixels.hpp"
#include "engine/sun/sun_search.hpp"

namespace lp {

// Luminance as the map's importance sampler and median cut weigh it by default.
inline constexpr LuminanceMode kSunLuminance = LuminanceMode::Average;

struct Sun {
  Direction axis{};  // the energy centroid of its core, unit, in the map's frame
  Vec3 direction;    // the same in floats
  PixelPos pixel;    // the pixel containing the direction
  PixelPos peak;     // its brightest pixel
  int64_t core_pixels = 0;
  double solid_angle = 0;     // Omega: the core's pixels' solid angles, summed
  double angular_radius = 0;  // r, the radius of a cone of solid angle Omega: 2 pi (1 - cos r) = Omega
  double removed_radius = 0;  // R: every pixel centre within R of the direction took `fill`
  int64_t removed_pixels = 0;
  Power fill{};         // the mean radiance of the ring around the removed pixels
  Power power{};        // the integral of its radiance over the sphere
  Power color{};        // its mean radiance over the cone: power / Omega
  Power irradiance{};   // on a surface facing it: power (1 + cos r) / 2, as from a uniform disc of radius r
  double share = 0;     // the luminance of `power` over the map's
  double contrast = 0;  // the luminance of `color` over `fill`'s: how much brighter than the sky around it
};

// Sets power and what follows from it (color, irradiance, share, contrast; `fill` set before);
// `map_luminance` is the luminance of the map's power.
void set_sun_power(Sun& sun, const Power& power, double map_luminance);

// 2 pi (1 - cos r) without the cancellation of 1 - cos r near 0.
double cone_solid_angle(double radius);
// The r of a cone of solid angle omega.
double cone_radius(double solid_angle);

}  // namespace lp
