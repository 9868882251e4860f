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

// What the check read from the header, for the decoder to confirm it reads the same (two parsers of one
// header must agree, or the check would not cover what is decoded).
struct ExrHeaderSummary {
  int min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // the data window
  int compression = 0;                             // exr_compression_t / Imf::Compression
};

// Throws lp::Error: Corrupt when the file cannot hold the pixels of its data window, TooLarge over the
// limits, Unsupported for deep images.
ExrHeaderSummary check_exr_capacity(std::span<const uint8_t> bytes, const ImageLimits& limits);

}  // namespace lp
