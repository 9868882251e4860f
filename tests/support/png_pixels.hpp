#pragma once
// A PNG decoded to 8-bit RGB (stb_image), for tests of tone-mapped output.
#include <stb_image.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lp::test {

struct PngPixels {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 bytes per pixel, rows from the top; empty if the bytes are no PNG
};

inline PngPixels decode_png(std::span<const uint8_t> bytes) {
  PngPixels png;
  int channels = 0;
  stbi_uc* pixels =
      stbi_load_from_memory(bytes.data(), int(bytes.size()), &png.width, &png.height, &channels, 3);
  if (!pixels) return {};
  png.rgb.assign(pixels, pixels + size_t(png.width) * size_t(png.height) * 3);
  stbi_image_free(pixels);
  return png;
}

}  // namespace lp::test
