#pragma once
// From regions to lights: one direct pass over the pixels of every region (the regions partition the
// map, so O(W * H) in all) sums the region's power and the moments its placement needs.
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"
#include "engine/mediancut/region.hpp"

namespace lp {

enum class LightPlacement {
  Centroid,         // centroid of the sampling weight (luminance * solid angle)
  CentroidSquared,  // centroid weighted by the square of that weight: pulled towards the brightest pixels
  Center,           // the region's geometric centre
};

constexpr auto enum_entries(LightPlacement) {
  return std::to_array<EnumEntry<LightPlacement>>({{LightPlacement::Centroid, "centroid"},
                                                   {LightPlacement::CentroidSquared, "centroid_squared"},
                                                   {LightPlacement::Center, "center"}});
}

using Power = std::array<double, 3>;  // RGB, double so that sums over millions of pixels stay exact

struct MedianCutLight {
  Vec3 direction;                // unit, world z-up
  int pixel_x = 0, pixel_y = 0;  // the pixel containing the placement point
  double u = 0, v = 0;           // the placement point in [0, 1]^2
  Region region;
  Power power{};      // sum over the region of radiance * pixel solid angle
  double energy = 0;  // luminance of `power` in the luminance mode
};

double power_luminance(const Power& p, LuminanceMode mode);

std::vector<MedianCutLight> place_lights(const Image& image, const std::vector<Region>& regions,
                                         LightPlacement placement, LuminanceMode mode);

}  // namespace lp
