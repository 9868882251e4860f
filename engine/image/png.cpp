// 8-bit PNG previews: tone mapped linear radiance, through stb_image_write.
#include <stb_image_write.h>
#include <tbb/parallel_for.h>

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

std::vector<uint8_t> encode_png_rgb8(std::span<const uint8_t> rgb8, int width, int height) {
  // A fast zlib level: previews are requested interactively, latency matters more than size.
  static const bool level_set = (stbi_write_png_compression_level = 3, true);
  (void)level_set;
  if (rgb8.size() != size_t(width) * size_t(height) * 3)
    throw Error(ErrorKind::Internal, "PNG buffer size mismatch");
  std::vector<uint8_t> out;
  if (!stbi_write_png_to_func(append_to_byte_vector, &out, width, height, 3, rgb8.data(), width * 3))
    throw Error(ErrorKind::Internal, "cannot encode PNG");
  return out;
}

std::vector<uint8_t> write_png(const Image& image, const ToneMap& tone) {
  return encode_png_rgb8(tone_map_rgb8(image, tone), image.width(), image.height());
}

}  // namespace lp
