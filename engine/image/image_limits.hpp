#pragma once
// Size checks every reader makes before it allocates.
#include <cstdint>

#include <fmt/format.h>

#include "engine/core/error.hpp"
#include "engine/image/image_io.hpp"

namespace lp {

inline void check_image_size(int64_t width, int64_t height, const ImageLimits& limits) {
  if (width <= 0 || height <= 0)
    throw Error(ErrorKind::Corrupt, fmt::format("invalid image size {} x {}", width, height));
  if (width > limits.max_dimension || height > limits.max_dimension || width * height > limits.max_pixels)
    throw Error(ErrorKind::TooLarge, fmt::format("image of {} x {} pixels is over the limit of {} pixels", width,
                                                 height, limits.max_pixels));
  if (limits.before_allocation) limits.before_allocation(width, height);
}

}  // namespace lp
