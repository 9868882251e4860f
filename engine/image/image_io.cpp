#include "engine/image/image_io.hpp"

#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>

#include "engine/core/error.hpp"
#include "engine/image/encode_pixels8.hpp"

namespace lp {

const char* format_mime_type(ImageFormat f) {
  switch (f) {
    case ImageFormat::Exr:
      return "image/x-exr";
    case ImageFormat::Pfm:
      return "image/x-portable-floatmap";
    case ImageFormat::Hdr:
      return "image/vnd.radiance";
    case ImageFormat::Png:
      return "image/png";
    case ImageFormat::Jpeg:
      return "image/jpeg";
    case ImageFormat::Webp:
      return "image/webp";
  }
  return "application/octet-stream";
}

std::optional<ImageFormat> detect_format(std::span<const uint8_t> b) {
  auto starts_with = [&](std::string_view magic) {
    return b.size() >= magic.size() && std::memcmp(b.data(), magic.data(), magic.size()) == 0;
  };
  if (starts_with("\x76\x2f\x31\x01")) return ImageFormat::Exr;
  if (b.size() >= 3 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f') && std::isspace(b[2]))
    return ImageFormat::Pfm;
  if (starts_with("#?RADIANCE") || starts_with("#?RGBE")) return ImageFormat::Hdr;
  if (starts_with("\x89PNG\r\n\x1a\n")) return ImageFormat::Png;
  return std::nullopt;
}

DecodedImage read_image(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  const auto format = detect_format(bytes);
  if (!format || *format == ImageFormat::Png)
    throw Error(ErrorKind::Unsupported,
                "not an image format we read (expected OpenEXR, PFM or Radiance HDR)");
  Image image;
  switch (*format) {
    case ImageFormat::Exr:
      image = read_exr(bytes, limits);
      break;
    case ImageFormat::Pfm:
      image = read_pfm(bytes, limits);
      break;
    default:
      image = read_hdr(bytes, limits);
      break;
  }
  return {std::move(image), *format};
}

DecodedImage read_image_file(const std::filesystem::path& path, const ImageLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::NotFound, "cannot open " + path.string());
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return read_image(bytes, limits);
}

std::vector<uint8_t> write_image(const Image& image, ImageFormat format, const ToneMap& tone) {
  switch (format) {
    case ImageFormat::Exr:
      return write_exr(image);
    case ImageFormat::Pfm:
      return write_pfm(image);
    case ImageFormat::Hdr:
      return write_hdr(image);
    case ImageFormat::Png:
      return write_png(image, tone);
    case ImageFormat::Jpeg:
    case ImageFormat::Webp:
      return encode_pixels8({tone_map_rgb8(image, tone), image.width(), image.height(), 3}, format);
  }
  throw Error(ErrorKind::InvalidArgument, "unknown output format");
}

void write_file(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) throw Error(ErrorKind::WriteFailed, "cannot write " + path.string());
}

}  // namespace lp
