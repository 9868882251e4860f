#pragma once
// The sun's core: the pixels connected to its peak whose luminance is at least `level`, neighbours
// being the eight around a pixel, across the seam in longitude and over the poles. Grown breadth first
// until it is complete or its solid angle passes `max_solid_angle` (then it is no compact emitter), so
// its work and memory are bounded by the pixels of that solid angle, and a bitmap of W x H bits.
#include <vector>

#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"
#include "engine/sun/sun_search.hpp"

namespace lp {

struct SunCore {
  std::vector<PixelPos> pixels;
  double solid_angle = 0;  // the pixels' exact solid angles, summed
  bool complete = false;   // false: it grew past max_solid_angle and `pixels` is a part of it
};

SunCore grow_sun_core(const Image& image, LuminanceMode mode, PixelPos peak, float level,
                      double max_solid_angle);

// The bytes grow_sun_core takes beyond the pixels it returns.
int64_t sun_core_scratch_bytes(int64_t width, int64_t height);

}  // namespace lp
