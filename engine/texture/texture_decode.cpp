#include "engine/texture/texture_decode.hpp"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

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

// Returns to the system the whole pages of `buffer` (a malloc'd block) below `end`: they are never read
// again, and the block is freed later as usual (its allocator's header lies before `buffer`).
void release_pages(const void* buffer, const void* end) {
#ifdef __linux__
  static const auto page = uintptr_t(sysconf(_SC_PAGESIZE));
  const uintptr_t first = (uintptr_t(buffer) + page - 1) / page * page;
  const uintptr_t last = uintptr_t(end) / page * page;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
  (void)buffer;
  (void)end;
#endif
}

// 8- or 16-bit samples to floats: colour channels through the sRGB curve when `space` says so, alpha
// always linear. The floats are written a stretch at a time, and the samples' pages already converted
// are released as they go, so that the two full-size buffers are never resident together.
template <class Sample>
std::vector<float> to_float(const Sample* samples, size_t texels, int channels, ColorSpace space) {
  constexpr float kMax = sizeof(Sample) == 1 ? 255.0f : 65535.0f;
  constexpr size_t kStretch = size_t{1} << 18;  // samples
  const size_t count = texels * size_t(channels);
  std::vector<float> out;
  out.reserve(count);  // pages not yet resident
  for (size_t begin = 0; begin < count; begin += kStretch) {
    const size_t end = std::min(count, begin + kStretch);
    out.resize(end);
    for (size_t i = begin; i < end; ++i) {
      const bool colour = space == ColorSpace::Srgb && int(i % size_t(channels)) < 3;
      if constexpr (sizeof(Sample) == 1)
        out[i] = colour ? srgb_table()[samples[i]] : float(samples[i]) / kMax;
      else
        out[i] = colour ? srgb_to_linear(float(samples[i]) / kMax) : float(samples[i]) / kMax;
    }
    release_pages(samples, samples + end);
  }
  return out;
}

// Channels of the texture made from a file of `file_channels`: grey and grey-alpha files become
// RGB(A); alpha is kept only when the file has it.
int texture_channels(int file_channels) {
  return (file_channels == 2 || file_channels == 4) ? 4 : 3;
}

Texture decode_stb(std::span<const uint8_t> bytes, ColorSpace space, const ImageLimits& limits,
                   const std::string& name) {
  const auto* data = bytes.data();
  const int length = int(bytes.size());
  int width = 0, height = 0, file_channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &file_channels))
    throw Error(ErrorKind::Corrupt, "texture " + name + ": " + stbi_failure_reason());
  check_image_size(width, height, limits);
  const int channels = texture_channels(file_channels);
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

int64_t texture_decode_bytes(std::span<const uint8_t> bytes, int64_t width, int64_t height) {
  const int64_t texels = width * height;
  if (is_png(bytes) || is_jpeg(bytes)) {
    int w = 0, h = 0, file_channels = 0;
    if (!stbi_info_from_memory(bytes.data(), int(bytes.size()), &w, &h, &file_channels)) return 0;
    const int channels = texture_channels(file_channels);
    const int64_t sample = stbi_is_16_bit_from_memory(bytes.data(), int(bytes.size())) ? 2 : 1;
    return mip_pyramid_bytes(width, height, channels) + texels * channels * sample;
  }
  // The image as read (at most four floats a texel), then the texture.
  return texels * 4 * int64_t(sizeof(float)) + mip_pyramid_bytes(width, height, 3);
}

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
