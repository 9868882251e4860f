#pragma once
// JPEG (baseline, 4:2:0 as stb_image_write writes it) of an 8-bit picture. JPEG has no alpha: the
// fourth channel of RGBA is left out.
#include <cstdint>
#include <vector>

#include "engine/image/pixels8.hpp"

namespace lp {

inline constexpr int kJpegQuality =
    90;  // of 1..100; 90 keeps edges of renders clean at a tenth of PNG's size

std::vector<uint8_t> encode_jpeg(const Pixels8& picture, int quality = kJpegQuality);

}  // namespace lp
