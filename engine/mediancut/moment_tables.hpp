#pragma once
// Summed-area tables of the first and second spatial moments of the sampling weight, which the
// variance-minimising split needs to evaluate a candidate half's variance in O(1).
// Coordinates are pixel centres (x + 0.5, y + 0.5).
#include "engine/envmap/luminance.hpp"
#include "engine/image/image.hpp"
#include "engine/mediancut/summed_area_table.hpp"

namespace lp {

struct MomentTables {
  SummedAreaTable wx, wy, wxx, wyy;  // weight * x, weight * y, weight * x^2, weight * y^2

  static int64_t memory_bytes(int64_t width, int64_t height) {
    return 4 * SummedAreaTable::memory_bytes(width, height);
  }
};

// The sampling weight of a pixel: luminance * exact pixel solid angle (proportional to
// luminance * sin(theta of the row centre), so the same distribution as the sampler, but in units
// of energy).
SummedAreaTable build_weight_table(const Image& image, LuminanceMode mode);
MomentTables build_moment_tables(const Image& image, LuminanceMode mode);

}  // namespace lp
