#pragma once
// Where a map's sun may be: its brightest pixels by radiance. A sun is the brightest thing in the sky
// however little of the map's power it carries, so the candidates are the `count` brightest pixels,
// brightest first; the detection (sun_detection.hpp) grows each into a core and keeps the first that is
// small and far brighter than its surroundings. One pass over the map, a heap of `count` entries.
#include <vector>

#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"

namespace lp {

struct PixelPos {
  int x = 0, y = 0;
};

// Brightest first; ties go to the first pixel in row-major order. count >= 1.
std::vector<PixelPos> brightest_pixels(const Image& image, LuminanceMode mode, int count);

}  // namespace lp
