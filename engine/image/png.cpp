// 8-bit PNG previews: tone mapped linear radiance, through stb_image_write.
#include <stb_image_write.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/byte_sink.hpp"
#include "engine/image/tonemap.hpp"

namespace lp {
std::vector<uint8_t> tone_map_rgb8(const Image& image, const ToneMap& tone) {
  const ToneMapper map(tone);
  const auto src = image.data();
  std::vector<uint8_t> pixels(src.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, src.size() / 3, 1 << 14),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) map(&src[3 * i], &pixels[3 * i]);
                    });
  return pixels;
}

std::vector<uint8_t> tone_map_rgba8(const Image& color, const Image& alpha, const ToneMap& tone) {
  if (alpha.width() != color.width() || alpha.height() != color.height())
    throw Error(ErrorKind::Internal, "RGBA: the alpha does not match the colour's size");
  const ToneMapper map(tone);
  const auto src = color.data(), a = alpha.data();
  const size_t pixels = src.size() / 3;
  std::vector<uint8_t> out(pixels * 4);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 1 << 14), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      const float coverage = std::clamp(a[i * 3], 0.0f, 1.0f);
      float rgb[3] = {0, 0, 0};
      if (coverage > 0)
        for (size_t c = 0; c < 3; ++c) rgb[c] = src[i * 3 + c] / coverage;
      map(rgb, &out[i * 4]);
      out[i * 4 + 3] = uint8_t(std::lround(coverage * 255.0f));
    }
  });
  return out;
}

namespace {

std::vector<uint8_t> encode_png8(std::span<const uint8_t> bytes, int width, int height, int channels) {
  // A fast zlib level: previews are requested interactively, latency matters more than size.
  static const bool level_set = (stbi_write_png_compression_level = 3, true);
  (void)level_set;
  if (bytes.size() != size_t(width) * size_t(height) * size_t(channels))
    throw Error(ErrorKind::Internal, "PNG buffer size mismatch");
  std::vector<uint8_t> out;
  if (!stbi_write_png_to_func(append_to_byte_vector, &out, width, height, channels, bytes.data(),
                              width * channels))
    throw Error(ErrorKind::Internal, "cannot encode PNG");
  return out;
}

}  // namespace

std::vector<uint8_t> encode_png_rgb8(std::span<const uint8_t> rgb8, int width, int height) {
  return encode_png8(rgb8, width, height, 3);
}

std::vector<uint8_t> encode_png_rgba8(std::span<const uint8_t> rgba8, int width, int height) {
  return encode_png8(rgba8, width, height, 4);
}

std::vector<uint8_t> write_png(const Image& image, const ToneMap& tone) {
  return encode_png_rgb8(tone_map_rgb8(image, tone), image.width(), image.height());
}

}  // namespace lp
