#pragma once
// Before the OpenEXR library allocates anything a header claims (its line offset table and buffers are
// sized by the data window), check the size against the limits and that the file holds the pixels:
// the offset table fits in the file, every chunk of the first part lies inside the file, and the
// chunks' compressed bytes are enough to expand to the claimed pixels at the best ratio the
// compression can reach.
#include <cstdint>
#include <span>

#include "engine/image/image_io.hpp"

namespace lp {

// Throws lp::Error: Corrupt when the file cannot hold the pixels of its data window, TooLarge over the
// limits, Unsupported for deep images.
void check_exr_capacity(std::span<const uint8_t> bytes, const ImageLimits& limits);

}  // namespace lp
