#include "engine/texture/texture_decode.hpp"

#include <stb_image.h>

#include <array>
#include <cmath>
#include <cstring>
#include <memory>

#include "engine/core/error.hpp"
#include "engine/image/image_limits.hpp"
#include "engine/texture/srgb.hpp"

namespace lp {
namespace {

bool is_png(std::span<const uint8_t> b) {
  return b.size() >= 8 && std::memcmp(b.data(), "\x89PNG\r\n\x1a\n", 8) == 0;
}
bool is_jpeg(std::span<const uint8_t> b) {
  return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
}

const std::array<float, 256>& srgb_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgb_to_linear(float(i) / 255.0f);
    return t;
  }();
  return table;
}

// 8- or 16-bit samples to floats: colour channels through the sRGB curve when `space` says so, alpha
// always linear.
template <class Sample>
std::vector<float> to_float(const Sample* samples, size_t texels, int channels, ColorSpace space) {
  constexpr float kMax = sizeof(Sample) == 1 ? 255.0f : 65535.0f;
  std::vector<float> out(texels * size_t(channels));
  for (size_t i = 0; i < out.size(); ++i) {
    const bool colour = space == ColorSpace::Srgb && int(i % size_t(channels)) < 3;
    if constexpr (sizeof(Sample) == 1)
      out[i] = colour ? srgb_table()[samples[i]] : float(samples[i]) / kMax;
    else
      out[i] = colour ? srgb_to_linear(float(samples[i]) / kMax) : float(samples[i]) / kMax;
  }
  return out;
}

Texture decode_stb(std::span<const uint8_t> bytes, ColorSpace space, const ImageLimits& limits,
                   const std::string& name) {
  const auto* data = bytes.data();
  const int length = int(bytes.size());
  int width = 0, height = 0, file_channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &file_channels))
    throw Error(ErrorKind::Corrupt, "texture " + name + ": " + stbi_failure_reason());
  check_image_size(width, height, limits);
  // Grey and grey-alpha files become RGB(A); alpha is kept only when the file has it.
  const int channels = (file_channels == 2 || file_channels == 4) ? 4 : 3;
  const size_t texels = size_t(width) * size_t(height);
  const bool sixteen = stbi_is_16_bit_from_memory(data, length);
  std::vector<float> values;
  int w = 0, h = 0, c = 0;
  if (sixteen) {
    std::unique_ptr<stbi_us, void (*)(void*)> p(stbi_load_16_from_memory(data, length, &w, &h, &c, channels),
                                                stbi_image_free);
    if (!p) throw Error(ErrorKind::Corrupt, "texture " + name + ": " + stbi_failure_reason());
    values = to_float(p.get(), texels, channels, space);
  } else {
    std::unique_ptr<stbi_uc, void (*)(void*)> p(stbi_load_from_memory(data, length, &w, &h, &c, channels),
                                                stbi_image_free);
    if (!p) throw Error(ErrorKind::Corrupt, "texture " + name + ": " + stbi_failure_reason());
    values = to_float(p.get(), texels, channels, space);
  }
  if (w != width || h != height)
    throw Error(ErrorKind::Corrupt, "texture " + name + ": size changed while decoding");
  return Texture(width, height, channels, std::move(values));
}

}  // namespace

Texture decode_texture(std::span<const uint8_t> bytes, ColorSpace space, const ImageLimits& limits,
                       const std::string& name) {
  if (is_png(bytes) || is_jpeg(bytes)) return decode_stb(bytes, space, limits, name);
  if (!detect_format(bytes))
    throw Error(
        ErrorKind::Unsupported,
        "texture " + name + " is not an image format we read (PNG, JPEG, OpenEXR, Radiance HDR, PFM)");
  Image image = read_image(bytes, limits).image;
  const auto data = image.data();
  for (float v : data)
    if (!std::isfinite(v))
      throw Error(ErrorKind::InvalidData, "texture " + name + " holds a non-finite value");
  return Texture(image.width(), image.height(), 3, std::vector<float>(data.begin(), data.end()));
}

}  // namespace lp
