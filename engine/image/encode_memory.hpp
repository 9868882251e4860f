#pragma once
// Upper bounds of the memory the encoders use beyond their input image: the encoded bytes (grown
// geometrically, so up to twice their final size) and the encoders' working buffers.
#include <cstdint>

#include "engine/image/image_io.hpp"

namespace lp {

// encode_png_rgb8: stb's filtered rows (3 B/px) and zlib stream, and the bytes handed back.
inline int64_t png_rgb8_encode_bytes(int64_t width, int64_t height) {
  return 12 * width * height + (1 << 20);
}

// encode_jpeg, encode_webp: the encoders' planes (WebP: ARGB, 4 B/px, and YUV) and the bytes handed back.
inline int64_t rgb8_lossy_encode_bytes(int64_t width, int64_t height) {
  return 10 * width * height + (1 << 20);
}

// write_image of a width x height float RGB image.
inline int64_t encode_bytes(ImageFormat format, int64_t width, int64_t height) {
  const int64_t pixels = width * height;
  switch (format) {
    case ImageFormat::Exr:
      return 24 * pixels + (4 << 20);  // 12 B/px of float RGB, grown by doubling
    case ImageFormat::Pfm:
      return 12 * pixels + 4096;
    case ImageFormat::Hdr:
      return 8 * pixels + 4096;  // 4 B/px of RGBE, grown by doubling
    case ImageFormat::Png:
      return 3 * pixels + png_rgb8_encode_bytes(width, height);  // the tone-mapped pixels first
    case ImageFormat::Jpeg:
    case ImageFormat::Webp:
      return 3 * pixels + rgb8_lossy_encode_bytes(width, height);
  }
  return 24 * pixels;
}

}  // namespace lp
