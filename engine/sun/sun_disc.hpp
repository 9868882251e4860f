#pragma once
// The disc of pixels a sun is removed from and the ring around it that says what the sky there is: the
// pixel centres within `radius` of the sun's axis, and those from `radius` to `ring_radius`. Rows are
// scanned in parallel (oneTBB) and summed in row order, so the sums do not depend on the thread count.
#include <cstdint>

#include "engine/image/image.hpp"
#include "engine/mediancut/light_placement.hpp"
#include "engine/sun/cone_pixels.hpp"

namespace lp {

struct DiscSums {
  Power disc{};  // sum of radiance * pixel solid angle over the disc
  double disc_solid_angle = 0;
  int64_t disc_pixels = 0;
  Power ring{};
  double ring_solid_angle = 0;

  // The ring's solid-angle-weighted mean radiance (0 for an empty ring).
  Power ring_mean() const;
};

DiscSums sum_disc_and_ring(const Image& image, const Direction& axis, double radius, double ring_radius);

// Sets every pixel of the disc to `fill`.
void fill_disc(Image& image, const Direction& axis, double radius, const Power& fill);

}  // namespace lp
