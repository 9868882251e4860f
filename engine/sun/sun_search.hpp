#pragma once
// Where a map's sun is, found on the median-cut weight table (luminance * pixel solid angle): the
// square window of `window` pixels (about the largest sun's diameter) that holds the most energy, then
// the brightest pixel in and around it. A few lookups per window, so the whole map is searched in
// O(W H / window^2); windows overlap by half and wrap around in longitude.
#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"
#include "engine/mediancut/summed_area_table.hpp"

namespace lp {

struct PixelPos {
  int x = 0, y = 0;
};

// `weight` is the table of `image` in luminance `mode`; window >= 1. The same answer whatever the
// thread count (ties go to the first window and pixel in row-major order).
PixelPos brightest_spot(const Image& image, const SummedAreaTable& weight, LuminanceMode mode, int window);

}  // namespace lp
