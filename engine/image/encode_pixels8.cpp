#include "engine/image/encode_pixels8.hpp"

#include "engine/image/jpeg.hpp"
#include "engine/image/webp.hpp"

namespace lp {
namespace {

// Straight RGBA bytes shown over white, as RGB bytes.
std::vector<uint8_t> over_white(std::span<const uint8_t> rgba) {
  std::vector<uint8_t> rgb(rgba.size() / 4 * 3);
  for (size_t i = 0; i < rgba.size() / 4; ++i) {
    const int a = rgba[i * 4 + 3];
    for (size_t c = 0; c < 3; ++c)
      rgb[i * 3 + c] = uint8_t((rgba[i * 4 + c] * a + 255 * (255 - a) + 127) / 255);
  }
  return rgb;
}

}  // namespace

std::vector<uint8_t> encode_pixels8(const Pixels8& picture, ImageFormat format) {
  switch (format) {
    case ImageFormat::Png:
      check_pixels8(picture, "PNG");
      return picture.channels == 4 ? encode_png_rgba8(picture.bytes, picture.width, picture.height)
                                   : encode_png_rgb8(picture.bytes, picture.width, picture.height);
    case ImageFormat::Jpeg:
      if (picture.channels == 4) {
        check_pixels8(picture, "JPEG");
        const std::vector<uint8_t> rgb = over_white(picture.bytes);
        return encode_jpeg({rgb, picture.width, picture.height, 3});
      }
      return encode_jpeg(picture);
    case ImageFormat::Webp:
      return encode_webp(picture);
    default:
      throw Error(ErrorKind::InvalidArgument,
                  std::string("not an 8-bit format: ") + std::string(enum_name(format)));
  }
}

}  // namespace lp
