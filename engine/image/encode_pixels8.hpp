#pragma once
// An 8-bit picture in one of the 8-bit formats (is_eight_bit): PNG and WebP, RGB or RGBA; JPEG, which has
// no alpha, of RGB or of RGBA shown over white (as a page of a white background shows the PNG).
#include <cstdint>
#include <vector>

#include "engine/image/image_io.hpp"
#include "engine/image/pixels8.hpp"

namespace lp {

// Throws lp::Error(InvalidArgument) for a format that is not 8-bit.
std::vector<uint8_t> encode_pixels8(const Pixels8& picture, ImageFormat format);

}  // namespace lp
