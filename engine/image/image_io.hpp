#pragma once
// Reading and writing images. Readers detect the format from the magic bytes and check sizes against
// limits and against the bytes present before allocating. Pixel values come back as stored: what a
// map does with NaN, Inf and negative values is the environment map's policy (envmap/invalid_pixels.hpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/core/limits.hpp"
#include "engine/image/image.hpp"

namespace lp {

// Jpeg and Webp are written only (8-bit, tone mapped, as PNG), for thumbnails and previews.
enum class ImageFormat { Exr, Pfm, Hdr, Png, Jpeg, Webp };

constexpr auto enum_entries(ImageFormat) {
  return std::to_array<EnumEntry<ImageFormat>>({{ImageFormat::Png, "png"},
                                                {ImageFormat::Exr, "exr"},
                                                {ImageFormat::Pfm, "pfm"},
                                                {ImageFormat::Hdr, "hdr"},
                                                {ImageFormat::Jpeg, "jpeg"},
                                                {ImageFormat::Webp, "webp"}});
}
// Whether the format holds 8-bit tone-mapped pixels (PNG, JPEG, WebP) rather than linear radiance.
constexpr bool is_eight_bit(ImageFormat f) {
  return f == ImageFormat::Png || f == ImageFormat::Jpeg || f == ImageFormat::Webp;
}
const char* format_mime_type(ImageFormat f);

struct ImageLimits {
  int64_t max_pixels = limits::kDefaultMaxImagePixels;
  int max_dimension = limits::kMaxImageDimension;
  // Called with the size of the image a reader is about to allocate, once its size passed the checks
  // (perhaps more than once for one image); it may throw to refuse the allocation (a memory budget).
  std::function<void(int64_t width, int64_t height)> before_allocation;
};

// The format from the first bytes, or nullopt if none we read.
std::optional<ImageFormat> detect_format(std::span<const uint8_t> bytes);

struct DecodedImage {
  Image image;
  ImageFormat format;
};

// Throws lp::Error: Unsupported (unknown magic), Corrupt, TooLarge, InvalidData.
DecodedImage read_image(std::span<const uint8_t> bytes, const ImageLimits& limits = {});
DecodedImage read_image_file(const std::filesystem::path& path, const ImageLimits& limits = {});

// Per-format readers (the bytes must be of that format).
Image read_pfm(std::span<const uint8_t> bytes, const ImageLimits& limits);
Image read_exr(std::span<const uint8_t> bytes, const ImageLimits& limits);
Image read_hdr(std::span<const uint8_t> bytes, const ImageLimits& limits);

// The curve that takes scaled linear radiance to display values (engine/image/tonemap.hpp).
enum class ToneCurve { Standard, Neutral, Agx, Aces, Reinhard };
constexpr auto enum_entries(ToneCurve) {
  return std::to_array<EnumEntry<ToneCurve>>({{ToneCurve::Standard, "standard"},
                                              {ToneCurve::Neutral, "neutral"},
                                              {ToneCurve::Agx, "agx"},
                                              {ToneCurve::Aces, "aces"},
                                              {ToneCurve::Reinhard, "reinhard"}});
}

// Preview settings for 8-bit output: scale by 2^exposure, apply `curve`, then gamma (nullopt = the
// sRGB curve).
struct ToneMap {
  float exposure = 0.0f;
  std::optional<float> gamma;
  ToneCurve curve = ToneCurve::Standard;
};

enum class ExrCompression { Zip, None };  // None: several times faster to write, for noisy images
// The bits of each channel in a file: 32-bit float, or 16-bit half float (IEEE 754 binary16).
enum class PixelPrecision { Float, Half };
constexpr auto enum_entries(PixelPrecision) {
  return std::to_array<EnumEntry<PixelPrecision>>(
      {{PixelPrecision::Float, "float"}, {PixelPrecision::Half, "half"}});
}
std::vector<uint8_t> write_exr(const Image& image, ExrCompression compression = ExrCompression::Zip,
                               PixelPrecision precision = PixelPrecision::Float);  // RGB
// One channel of an OpenEXR file: its name and its values, `stride` floats apart in row-major order.
struct ExrChannel {
  std::string name;
  const float* data;
  size_t stride;
};
// Any channels, as 32-bit floats (OpenEXR stores them sorted by name).
std::vector<uint8_t> write_exr_channels(int width, int height, std::span<const ExrChannel> channels,
                                        ExrCompression compression = ExrCompression::Zip);
// R, G, B from `color` (premultiplied by alpha, as a transparent render's colour is) and A from the
// first channel of `alpha`.
std::vector<uint8_t> write_exr_rgba(const Image& color, const Image& alpha,
                                    ExrCompression compression = ExrCompression::Zip);
std::vector<uint8_t> write_pfm(const Image& image);  // little-endian, rows bottom to top
std::vector<uint8_t> write_hdr(const Image& image);  // Radiance RGBE
std::vector<uint8_t> write_png(const Image& image, const ToneMap& tone = {});  // 8-bit RGB
std::vector<uint8_t> write_image(const Image& image, ImageFormat format, const ToneMap& tone = {});

// 8-bit previews that draw on top of the tone-mapped image: tone map, paint, then encode.
std::vector<uint8_t> tone_map_rgb8(const Image& image, const ToneMap& tone);  // w * h * 3 bytes
std::vector<uint8_t> encode_png_rgb8(std::span<const uint8_t> rgb8, int width, int height);
// 8-bit RGBA with straight alpha from a premultiplied colour and its alpha (the first channel of `alpha`):
// each colour is divided by its alpha before the tone map (black where alpha is 0). w * h * 4 bytes.
std::vector<uint8_t> tone_map_rgba8(const Image& color, const Image& alpha, const ToneMap& tone);
std::vector<uint8_t> encode_png_rgba8(std::span<const uint8_t> rgba8, int width, int height);

void write_file(const std::filesystem::path& path, std::span<const uint8_t> bytes);

}  // namespace lp
