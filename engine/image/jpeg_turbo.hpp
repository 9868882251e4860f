#pragma once
// JPEG through libjpeg-turbo, for files whose structure we assemble ourselves (engine/image/ultrahdr):
// baseline, 4:4:4 (no chroma subsampling), no JFIF or other marker, so the caller adds its own; and a
// bounded decoder of 8-bit RGB. Library failures come back as lp::Error, never as an exit.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/image/image_io.hpp"
#include "engine/image/pixels8.hpp"

namespace lp {

// How the channels are coded: YCbCr (JPEG's usual, what every viewer expects of a picture), or RGB as
// given (an APP14 Adobe marker with transform 0 says so), which spares data that is not a picture the
// rounding of the colour transform.
enum class JpegColours { YCbCr, Untransformed };

// SOI, the tables, the frame and the scan, EOI: no APPn marker but APP14 for RGB.
std::vector<uint8_t> encode_jpeg_444(const Pixels8& picture, int quality,
                                     JpegColours colours = JpegColours::YCbCr);

struct DecodedJpeg {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 bytes a pixel, rows top to bottom
};

// Throws lp::Error: Corrupt (not a JPEG libjpeg can decode), TooLarge (over `limits`).
DecodedJpeg decode_jpeg_rgb(std::span<const uint8_t> bytes, const ImageLimits& limits);

}  // namespace lp
